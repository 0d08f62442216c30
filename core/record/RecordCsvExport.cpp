#include "core/record/RecordCsvExport.h"

#include "core/record/CsvFile.h"
#include "core/record/CsvText.h"
#include "core/record/RecordData.h"
#include "core/util/Units.h"

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <stdexcept>

namespace hsmu {

namespace {

using csvtext::quoted;

// The output unit of each console unit of the record's columns ("m", "m/s", "m/s^2", "rad",
// "kN", "kN m", "s"; others, "-" and "", unchanged).
class UnitMap {
public:
    explicit UnitMap(const ExportUnits& u) {
        const auto pick = [](const std::string& text, units::Dimension d) {
            return text.empty() ? units::Unit{units::baseSymbol(d), d, 1.0} : *units::parse(text, d);
        };
        m_length = pick(u.length, units::Dimension::Length);
        m_force = pick(u.force, units::Dimension::Force);
        m_rotation = pick(u.rotation, units::Dimension::Rotation);
        m_time = pick(u.time, units::Dimension::Time);
        m_moment = !u.moment.empty() ? pick(u.moment, units::Dimension::Moment)
                   : (u.force.empty() && u.length.empty())
                       ? pick("", units::Dimension::Moment)
                       : units::Unit{m_force.symbol + " " + m_length.symbol,
                                     units::Dimension::Moment, m_force.factor * m_length.factor};
    }
    /// The output symbol of a column in `consoleUnit`.
    std::string symbol(const std::string& consoleUnit) const { return map(consoleUnit).first; }
    /// A value in `consoleUnit` written in the output unit.
    std::string number(double v, const std::string& consoleUnit) const {
        return csvtext::number(v / map(consoleUnit).second);
    }

private:
    std::pair<std::string, double> map(const std::string& c) const {
        if (c == "m")
            return {m_length.symbol, m_length.factor};
        if (c == "m/s")
            return {m_length.symbol + "/" + m_time.symbol, m_length.factor / m_time.factor};
        if (c == "m/s^2")
            return {m_length.symbol + "/" + m_time.symbol + "^2",
                    m_length.factor / (m_time.factor * m_time.factor)};
        if (c == "rad")
            return {m_rotation.symbol, m_rotation.factor};
        if (c == "kN")
            return {m_force.symbol, m_force.factor};
        if (c == "kN m")
            return {m_moment.symbol, m_moment.factor};
        if (c == "s")
            return {m_time.symbol, m_time.factor};
        return {c, 1.0};
    }
    units::Unit m_length, m_force, m_rotation, m_moment, m_time;
};

std::string number(double v) {
    return csvtext::number(v);
}

std::vector<std::string> stepAndTime(const RecordData& r, Eigen::Index i, const UnitMap& u) {
    return {std::to_string(r.steps[std::size_t(i)]), u.number(r.time[i], "s")};
}

void writeSteps(const RecordData& r, const std::filesystem::path& dir,
                std::vector<std::string>& written, const UnitMap& u) {
    CsvFile f((dir / "steps.csv").string(), written);
    f.column("step", "");
    f.column("time", u.symbol("s"));
    f.column("ground_acceleration", u.symbol("m/s^2"));
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i, u);
        row.push_back(u.number(r.groundAcceleration[i], "m/s^2"));
        f.line(row);
    }
    f.close();
}

void writeDofs(const RecordData& r, const std::filesystem::path& dir,
               std::vector<std::string>& written, const UnitMap& u) {
    CsvFile f((dir / "dofs.csv").string(), written);
    f.column("step", "");
    f.column("time", u.symbol("s"));
    const std::pair<const char*, const char*> kinds[] = {{"u", "m"}, {"v", "m/s"}, {"a", "m/s^2"}};
    for (const auto& [kind, unit] : kinds)
        for (const auto& name : r.layout.dofNames)
            f.column(std::string(kind) + " " + name, u.symbol(unit));
    f.endHeader();
    const std::pair<const Eigen::MatrixXd*, const char*> matrices[] = {
        {&r.u, "m"}, {&r.v, "m/s"}, {&r.a, "m/s^2"}};
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i, u);
        for (const auto& [m, unit] : matrices)
            for (Eigen::Index j = 0; j < m->cols(); ++j)
                row.push_back(u.number((*m)(i, j), unit));
        f.line(row);
    }
    f.close();
}

void writeElements(const RecordData& r, const std::filesystem::path& dir,
                   std::vector<std::string>& written, const UnitMap& u) {
    CsvFile f((dir / "elements.csv").string(), written);
    f.column("step", "");
    f.column("time", u.symbol("s"));
    for (const ElementInfo& e : r.layout.elements) {
        f.column(e.name + " deformation", u.symbol(e.units.deformation));
        f.column(e.name + " force", u.symbol(e.units.force));
        f.column(e.name + " commanded", u.symbol(e.units.deformation));
    }
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i, u);
        for (Eigen::Index j = 0; j < Eigen::Index(r.layout.elements.size()); ++j) {
            const ElementUnits& eu = r.layout.elements[std::size_t(j)].units;
            row.push_back(u.number(r.deformation(i, j), eu.deformation));
            row.push_back(u.number(r.force(i, j), eu.force));
            row.push_back(u.number(r.commanded(i, j), eu.deformation));
        }
        f.line(row);
    }
    f.close();
}

/// actuators.csv: the actuator channels of every specimen (records that have them).
void writeActuators(const RecordData& r, const std::filesystem::path& dir,
                    std::vector<std::string>& written, const UnitMap& u) {
    const Eigen::Index n = Eigen::Index(r.layout.elements.size());
    if (r.actuatorCommanded.rows() != r.rows() || r.actuatorCommanded.cols() != n ||
        std::none_of(r.layout.elements.begin(), r.layout.elements.end(),
                     [](const ElementInfo& e) { return e.experimental; }))
        return;
    CsvFile f((dir / "actuators.csv").string(), written);
    f.column("step", "");
    f.column("time", u.symbol("s"));
    for (const ElementInfo& e : r.layout.elements) {
        if (!e.experimental)
            continue;
        f.column(e.name + " actuator commanded", u.symbol(e.units.deformation));
        f.column(e.name + " actuator measured", u.symbol(e.units.deformation));
        f.column(e.name + " held ticks", "-");
        f.column(e.name + " flags", "-");
    }
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i, u);
        for (Eigen::Index j = 0; j < n; ++j) {
            const ElementInfo& e = r.layout.elements[std::size_t(j)];
            if (!e.experimental)
                continue;
            row.push_back(u.number(r.actuatorCommanded(i, j), e.units.deformation));
            row.push_back(u.number(r.actuatorMeasured(i, j), e.units.deformation));
            row.push_back(number(r.heldTicks(i, j)));
            row.push_back(number(r.actuatorFlags(i, j)));
        }
        f.line(row);
    }
    f.close();
}

void writeSites(const RecordData& r, const std::filesystem::path& dir,
                std::vector<std::string>& written, const UnitMap& u) {
    const auto n = r.siteRoundTrip.cols();
    if (n == 0 || r.siteRoundTrip.rows() != r.rows())
        return;
    CsvFile f((dir / "sites.csv").string(), written);
    f.column("step", "");
    f.column("time", u.symbol("s"));
    for (Eigen::Index j = 0; j < n; ++j)
        f.column((std::size_t(j) < r.layout.sites.size() ? r.layout.sites[std::size_t(j)]
                                                         : "site " + std::to_string(j + 1)) +
                     " round trip",
                 u.symbol("s"));
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i, u);
        for (Eigen::Index j = 0; j < n; ++j)
            row.push_back(u.number(r.siteRoundTrip(i, j), "s"));
        f.line(row);
    }
    f.close();
}

void writeUpdating(const RecordData& r, const std::filesystem::path& dir,
                   std::vector<std::string>& written, const UnitMap& u) {
    const UpdatingInfo& info = *r.layout.updating;
    const bool v2 = r.tracking.rows() == r.rows() && r.rows() > 0;
    CsvFile f((dir / "updating.csv").string(), written);
    f.column("step", "");
    f.column("time", u.symbol("s"));
    for (const auto& p : info.parameters)
        f.column(p, "-");
    for (const auto& p : info.parameters)
        f.column("stddev " + p, "-");
    f.column("auxiliary_force", u.symbol(info.units.force));
    for (const char* name :
         {"fit_error", "applied_updates", "updates_this_step", "pending_proposals"})
        f.column(name, "-");
    if (v2) {
        f.column("tracking_j1", u.symbol("s"));
        f.column("tracking_j2", "-");
        f.column("tracking_j3", "-");
        f.column("update_requested", "-");
    }
    f.endHeader();
    for (Eigen::Index i = 0; i < r.rows(); ++i) {
        auto row = stepAndTime(r, i, u);
        for (const Eigen::MatrixXd* m : {&r.parameters, &r.stddev})
            for (Eigen::Index j = 0; j < m->cols(); ++j)
                row.push_back(number((*m)(i, j)));
        row.push_back(u.number(r.auxiliaryForce[i], info.units.force));
        row.push_back(number(r.fitError[i]));
        for (const std::vector<int>* v :
             {&r.appliedUpdates, &r.updatesThisStep, &r.pendingProposals})
            row.push_back(std::to_string((*v)[std::size_t(i)]));
        if (v2) {
            for (Eigen::Index j = 0; j < r.tracking.cols(); ++j)
                row.push_back(j == 0 ? u.number(r.tracking(i, j), "s") : number(r.tracking(i, j)));
            row.push_back(std::to_string(r.updateRequested[std::size_t(i)]));
        }
        f.line(row);
    }
    f.close();

    CsvFile e((dir / "update_events.csv").string(), written);
    e.column("step", "");
    e.column("time", u.symbol("s"));
    e.column("element", "");
    for (const auto& p : info.parameters)
        e.column(p, "-");
    e.column("decision", "");
    e.column("proposal", "");
    e.endHeader();
    for (const RecordedUpdate& ev : r.updateEvents) {
        std::vector<std::string> row{std::to_string(ev.step), u.number(ev.time, "s"),
                                     quoted(ev.element)};
        for (double v : ev.values)
            row.push_back(number(v));
        row.push_back(quoted(ev.decision));
        row.push_back(std::to_string(ev.proposal));
        e.line(row);
    }
    e.close();
}

void writeLogs(const RecordData& r, const std::filesystem::path& dir,
               std::vector<std::string>& written, const UnitMap& u) {
    CsvFile a((dir / "alarms.csv").string(), written);
    a.column("time", u.symbol("s"));
    for (const char* name : {"step", "severity", "kind", "message", "code"})
        a.column(name, "");
    a.endHeader();
    for (const Alarm& al : r.alarms)
        a.line({u.number(al.time, "s"), std::to_string(al.step), alarmSeverityName(al.severity),
                quoted(alarmKindName(al.kind)), quoted(al.message), quoted(al.code)});
    a.close();

    CsvFile n((dir / "notes.csv").string(), written);
    n.column("time", u.symbol("s"));
    n.column("step", "");
    n.column("text", "");
    n.endHeader();
    for (const RecordNote& note : r.notes)
        n.line({u.number(note.time, "s"), std::to_string(note.step), quoted(note.text)});
    n.close();
}

} // namespace

ExportUnits parseExportUnits(const std::string& text) {
    ExportUnits u;
    std::istringstream s(text);
    std::string part;
    const auto trim = [](std::string v) {
        const auto b = v.find_first_not_of(" \t");
        const auto e = v.find_last_not_of(" \t");
        return b == std::string::npos ? std::string() : v.substr(b, e - b + 1);
    };
    while (std::getline(s, part, ',')) {
        const auto eq = part.find('=');
        const std::string key = trim(part.substr(0, eq));
        const std::string value = eq == std::string::npos ? std::string() : trim(part.substr(eq + 1));
        const struct {
            const char* key;
            std::string ExportUnits::*field;
            units::Dimension dimension;
        } keys[] = {{"length", &ExportUnits::length, units::Dimension::Length},
                    {"force", &ExportUnits::force, units::Dimension::Force},
                    {"rotation", &ExportUnits::rotation, units::Dimension::Rotation},
                    {"moment", &ExportUnits::moment, units::Dimension::Moment},
                    {"time", &ExportUnits::time, units::Dimension::Time}};
        const auto* k = std::find_if(std::begin(keys), std::end(keys),
                                     [&](const auto& x) { return key == x.key; });
        if (k == std::end(keys) || value.empty())
            throw std::invalid_argument("--units: expected KEY=UNIT pairs separated by commas "
                                        "with KEY one of length, force, rotation, moment, time "
                                        "(e.g. length=in,force=kip), found '" + part + "'");
        if (!units::parse(value, k->dimension))
            throw std::invalid_argument("--units: unknown " + key + " unit '" + value +
                                        "' (expected " + units::accepted(k->dimension) + ")");
        u.*(k->field) = value;
    }
    return u;
}

std::vector<std::string> exportRecordCsv(const RecordData& record, const std::string& dir,
                                         const ExportUnits& units) {
    const std::filesystem::path d(dir);
    const UnitMap u(units);
    std::vector<std::string> written;
    writeSteps(record, d, written, u);
    writeDofs(record, d, written, u);
    writeElements(record, d, written, u);
    writeActuators(record, d, written, u);
    writeSites(record, d, written, u);
    if (record.layout.updating)
        writeUpdating(record, d, written, u);
    writeLogs(record, d, written, u);
    return written;
}

} // namespace hsmu
