#include "core/record/RecordCsvExport.h"

#include "core/record/CsvFile.h"
#include "core/record/CsvText.h"
#include "core/record/RecordColumns.h"
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
            return text.empty() ? units::Unit{units::baseSymbol(d), d, 1.0}
                                : *units::parse(text, d);
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

/// One table of RecordColumns (core/record/RecordColumns.h): step, time, then its columns.
void writeTable(const RecordData& r, const RecordTable& table, const std::filesystem::path& dir,
                std::vector<std::string>& written, const UnitMap& u) {
    CsvFile f((dir / table.file).string(), written);
    const RecordColumn step = table.dofRows ? dofStepColumn() : stepColumn();
    const RecordColumn time = table.dofRows ? dofTimeColumn() : timeColumn();
    std::vector<const RecordColumn*> columns{&step, &time};
    for (const RecordColumn& c : table.columns)
        columns.push_back(&c);
    for (const RecordColumn* c : columns)
        f.column(c->name, u.symbol(c->unit));
    f.endHeader();
    std::vector<std::string> row;
    const Eigen::Index rows = table.dofRows ? r.dofRows() : r.rows();
    for (Eigen::Index i = 0; i < rows; ++i) {
        row.clear();
        for (const RecordColumn* c : columns) {
            const double v = c->value(r, i);
            row.push_back(c->integer ? std::to_string(static_cast<long long>(v))
                                     : u.number(v, c->unit));
        }
        f.line(row);
    }
    f.close();
}

void writeUpdateEvents(const RecordData& r, const std::filesystem::path& dir,
                       std::vector<std::string>& written, const UnitMap& u) {
    const UpdatingInfo& info = *r.layout.updating;
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
        const std::string value =
            eq == std::string::npos ? std::string() : trim(part.substr(eq + 1));
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
                                        "(e.g. length=in,force=kip), found '" +
                                        part + "'");
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
    for (const RecordTable& table : recordTables(record))
        writeTable(record, table, d, written, u);
    if (record.layout.updating)
        writeUpdateEvents(record, d, written, u);
    writeLogs(record, d, written, u);
    return written;
}

} // namespace hsmu
