#include "core/record/RecordCsvExport.h"

#include "core/record/CsvFile.h"
#include "core/record/CsvText.h"
#include "core/record/RecordData.h"

#include <filesystem>
#include <stdexcept>

namespace hsmu {

namespace {

using csvtext::number;
using csvtext::quoted;

std::vector<std::string> stepAndTime(const RecordData& r, Eigen::Index i) {
    return {std::to_string(r.steps[std::size_t(i)]), number(r.time[i])};
}

void writeSteps(const RecordData& r, const std::filesystem::path& dir,
                std::vector<std::string>& written) {
    CsvFile f((dir / "steps.csv").string(), written);
    f.column("step", "");
    f.column("time", "s");
    f.column("ground_acceleration", "m/s^2");
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i);
        row.push_back(number(r.groundAcceleration[i]));
        f.line(row);
    }
    f.close();
}

void writeDofs(const RecordData& r, const std::filesystem::path& dir,
               std::vector<std::string>& written) {
    CsvFile f((dir / "dofs.csv").string(), written);
    f.column("step", "");
    f.column("time", "s");
    const std::pair<const char*, const char*> kinds[] = {{"u", "m"}, {"v", "m/s"}, {"a", "m/s^2"}};
    for (const auto& [kind, unit] : kinds)
        for (const auto& name : r.layout.dofNames)
            f.column(std::string(kind) + " " + name, unit);
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i);
        for (const Eigen::MatrixXd* m : {&r.u, &r.v, &r.a})
            for (Eigen::Index j = 0; j < m->cols(); ++j)
                row.push_back(number((*m)(i, j)));
        f.line(row);
    }
    f.close();
}

void writeElements(const RecordData& r, const std::filesystem::path& dir,
                   std::vector<std::string>& written) {
    CsvFile f((dir / "elements.csv").string(), written);
    f.column("step", "");
    f.column("time", "s");
    for (const ElementInfo& e : r.layout.elements) {
        f.column(e.name + " deformation", e.units.deformation);
        f.column(e.name + " force", e.units.force);
        f.column(e.name + " commanded", e.units.deformation);
    }
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i);
        for (Eigen::Index j = 0; j < Eigen::Index(r.layout.elements.size()); ++j)
            for (const Eigen::MatrixXd* m : {&r.deformation, &r.force, &r.commanded})
                row.push_back(number((*m)(i, j)));
        f.line(row);
    }
    f.close();
}

void writeUpdating(const RecordData& r, const std::filesystem::path& dir,
                   std::vector<std::string>& written) {
    const UpdatingInfo& info = *r.layout.updating;
    const bool v2 = r.tracking.rows() == r.rows() && r.rows() > 0;
    CsvFile f((dir / "updating.csv").string(), written);
    f.column("step", "");
    f.column("time", "s");
    for (const auto& p : info.parameters)
        f.column(p, "-");
    for (const auto& p : info.parameters)
        f.column("stddev " + p, "-");
    f.column("auxiliary_force", info.units.force);
    for (const char* name :
         {"fit_error", "applied_updates", "updates_this_step", "pending_proposals"})
        f.column(name, "-");
    if (v2) {
        f.column("tracking_j1", "s");
        f.column("tracking_j2", "-");
        f.column("tracking_j3", "-");
        f.column("update_requested", "-");
    }
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i);
        for (const Eigen::MatrixXd* m : {&r.parameters, &r.stddev})
            for (Eigen::Index j = 0; j < m->cols(); ++j)
                row.push_back(number((*m)(i, j)));
        row.push_back(number(r.auxiliaryForce[i]));
        row.push_back(number(r.fitError[i]));
        for (const std::vector<int>* v :
             {&r.appliedUpdates, &r.updatesThisStep, &r.pendingProposals})
            row.push_back(std::to_string((*v)[std::size_t(i)]));
        if (v2) {
            for (Eigen::Index j = 0; j < r.tracking.cols(); ++j)
                row.push_back(number(r.tracking(i, j)));
            row.push_back(std::to_string(r.updateRequested[std::size_t(i)]));
        }
        f.line(row);
    }
    f.close();

    CsvFile e((dir / "update_events.csv").string(), written);
    e.column("step", "");
    e.column("time", "s");
    e.column("element", "");
    for (const auto& p : info.parameters)
        e.column(p, "-");
    e.endHeader();
    for (const RecordedUpdate& ev : r.updateEvents) {
        std::vector<std::string> row{std::to_string(ev.step), number(ev.time), quoted(ev.element)};
        for (double v : ev.values)
            row.push_back(number(v));
        e.line(row);
    }
    e.close();
}

void writeLogs(const RecordData& r, const std::filesystem::path& dir,
               std::vector<std::string>& written) {
    CsvFile a((dir / "alarms.csv").string(), written);
    a.column("time", "s");
    for (const char* name : {"step", "severity", "kind", "message"})
        a.column(name, "");
    a.endHeader();
    for (const Alarm& al : r.alarms)
        a.line({number(al.time), std::to_string(al.step), alarmSeverityName(al.severity),
                quoted(alarmKindName(al.kind)), quoted(al.message)});
    a.close();

    CsvFile n((dir / "notes.csv").string(), written);
    n.column("time", "s");
    n.column("step", "");
    n.column("text", "");
    n.endHeader();
    for (const RecordNote& note : r.notes)
        n.line({number(note.time), std::to_string(note.step), quoted(note.text)});
    n.close();
}

} // namespace

std::vector<std::string> exportRecordCsv(const RecordData& record, const std::string& dir) {
    const std::filesystem::path d(dir);
    std::vector<std::string> written;
    writeSteps(record, d, written);
    writeDofs(record, d, written);
    writeElements(record, d, written);
    if (record.layout.updating)
        writeUpdating(record, d, written);
    writeLogs(record, d, written);
    return written;
}

} // namespace hsmu
