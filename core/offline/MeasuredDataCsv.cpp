#include "core/offline/MeasuredDataCsv.h"

#include "core/util/InputLimits.h"
#include "core/util/Units.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace hsmu {

namespace {

enum Column { Time = 0, Deformation = 1, Force = 2 };
const char* const kColumnNames[] = {"time", "deformation", "force"};

[[noreturn]] void fail(const std::string& what) {
    throw MeasuredDataError(what);
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r\"");
    const auto e = s.find_last_not_of(" \t\r\"");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// What a column name says: its role, and whether a time column is a sample index.
struct Role {
    Column column;
    bool index = false;
};

std::optional<Role> roleOf(const std::string& name) {
    static const std::map<std::string, Role> names{{"time", {Time}},
                                                   {"t", {Time}},
                                                   {"step", {Time, true}},
                                                   {"k", {Time, true}},
                                                   {"index", {Time, true}},
                                                   {"sample", {Time, true}},
                                                   {"deformation", {Deformation}},
                                                   {"displacement", {Deformation}},
                                                   {"rotation", {Deformation}},
                                                   {"d", {Deformation}},
                                                   {"u", {Deformation}},
                                                   {"force", {Force}},
                                                   {"moment", {Force}},
                                                   {"load", {Force}},
                                                   {"lateral_load", {Force}},
                                                   {"f", {Force}}};
    auto it = names.find(lower(name));
    return it == names.end() ? std::nullopt : std::optional<Role>(it->second);
}

/// One header field: "time [s]", "force (kN m)", "displacement_mm", "lateral_load_g", "k".
struct HeaderField {
    std::string text;         ///< as written
    std::string name;         ///< without the unit
    std::string unit;         ///< "" if none
    std::optional<Role> role; ///< nullopt: not a column this reader knows
    bool unclosed = false;    ///< "name [unit" without the closing bracket
    std::string lastWord;     ///< an unknown NAME_UNIT's last '_' word ("raw_dist_mm": mm)
};

HeaderField parseHeaderField(const std::string& field) {
    HeaderField h{field, trim(field), "", std::nullopt, false, ""};
    const auto open = h.name.find_first_of("[(");
    if (open != std::string::npos) {
        const auto close = h.name.find_first_of("])", open);
        if (close == std::string::npos) {
            h.unclosed = true;
            return h;
        }
        h.unit = trim(h.name.substr(open + 1, close - open - 1));
        h.name = trim(h.name.substr(0, open));
        h.role = roleOf(h.name);
        return h;
    }
    h.role = roleOf(h.name);
    if (h.role) {
        return h;
    }
    // NAME_UNIT: the shortest known name before an underscore, the rest the unit (its own
    // underscores read as spaces: "moment_kN_m").
    for (auto us = h.name.find('_'); us != std::string::npos; us = h.name.find('_', us + 1)) {
        if (const auto role = roleOf(h.name.substr(0, us))) {
            h.role = role;
            h.unit = h.name.substr(us + 1);
            std::replace(h.unit.begin(), h.unit.end(), '_', ' ');
            h.name = h.name.substr(0, us);
            return h;
        }
    }
    if (const auto us = h.name.rfind('_'); us != std::string::npos)
        h.lastWord = h.name.substr(us + 1);
    return h;
}

std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> out;
    const bool delimited = line.find_first_of(",;\t") != std::string::npos;
    std::string field;
    std::istringstream s(line);
    if (delimited) {
        for (char ch : line) {
            if (ch == ',' || ch == ';' || ch == '\t') {
                out.push_back(trim(field));
                field.clear();
            } else {
                field.push_back(ch);
            }
        }
        out.push_back(trim(field));
    } else {
        while (s >> field)
            out.push_back(field);
    }
    return out;
}

bool parseNumber(const std::string& text, double& value) {
    if (text.empty())
        return false;
    const char* b = text.data();
    const char* e = b + text.size();
    if (*b == '+')
        ++b;
    const auto r = std::from_chars(b, e, value);
    return r.ec == std::errc() && r.ptr == e;
}

bool looksNumeric(const std::vector<std::string>& fields) {
    double x;
    return !fields.empty() && parseNumber(fields[0], x);
}

std::vector<std::string> splitBlanks(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream s(text);
    std::string word;
    while (s >> word)
        out.push_back(word);
    return out;
}

/// The fields of a "# columns:" comment for rows of `dataFields` values: split as a header
/// line is, or, if that gives fewer fields (a comma in the commentary after the names), at
/// blanks; words past dataFields are commentary.
std::vector<std::string> commentFields(const std::string& text, std::size_t dataFields) {
    std::vector<std::string> fields = splitFields(text);
    if (fields.size() < dataFields)
        fields = splitBlanks(text);
    if (fields.size() > dataFields)
        fields.resize(dataFields);
    return fields;
}

/// "# columns: a b c ..." (case-insensitive): the text after the colon; nullopt otherwise.
std::optional<std::string> commentColumns(const std::string& comment) {
    const std::string l = lower(comment);
    const auto key = l.find("columns");
    if (key == std::string::npos || trim(l.substr(1, key - 1)) != "")
        return std::nullopt;
    const auto colon = l.find_first_not_of(" \t", key + 7);
    if (colon == std::string::npos || l[colon] != ':')
        return std::nullopt;
    return trim(comment.substr(colon + 1));
}

const std::string& forceUnitsExpected() {
    static const std::string s = units::accepted(units::Dimension::Force) +
                                 ", g (the load in units of the specimen's weight), or a moment: " +
                                 units::accepted(units::Dimension::Moment);
    return s;
}

class Reader {
public:
    Reader(std::string source, const MeasuredDataOptions& options)
        : m_source(std::move(source)), m_options(options) {}

    [[noreturn]] void fail(int line, const std::string& what) const {
        throw MeasuredDataError(m_source + ": line " + std::to_string(line) + ": " + what);
    }

    /// Decide which fields are time, deformation and force, and their units as written, from
    /// the header (a header line or a "# columns:" comment, may be empty), --columns and
    /// --units.
    void resolveColumns(const std::vector<std::string>& header, int line) {
        m_headerLine = line;
        std::vector<HeaderField> fields;
        for (const std::string& f : header)
            fields.push_back(parseHeaderField(f));
        for (std::size_t i = 0; i < fields.size(); ++i)
            if (fields[i].unclosed)
                fail(line, "column " + std::to_string(i + 1) + ": unclosed unit in '" +
                               fields[i].text + "'");
        std::array<int, 3> picked{-1, -1, -1};
        if (m_options.columns) {
            const MeasuredDataColumns& c = *m_options.columns;
            picked = {c.time - 1, c.deformation - 1, c.force - 1};
        } else if (!fields.empty()) {
            for (std::size_t i = 0; i < fields.size(); ++i) {
                if (!fields[i].role)
                    continue;
                const Column c = fields[i].role->column;
                if (picked[c] >= 0) {
                    // A time and a sample index (an exported "step, time [s], ..."): the time.
                    const bool pickedIndex = fields[std::size_t(picked[c])].role->index;
                    if (c == Time && pickedIndex != fields[i].role->index) {
                        if (pickedIndex)
                            picked[c] = int(i);
                        continue;
                    }
                    fail(line, "column " + std::to_string(i + 1) + ": '" + fields[i].name +
                                   "' names the " + kColumnNames[c] + " a second time");
                }
                picked[c] = int(i);
            }
            if (std::find(picked.begin(), picked.end(), -1) != picked.end()) {
                for (std::size_t i = 0; i < fields.size(); ++i)
                    if (!fields[i].role)
                        fail(line, "column " + std::to_string(i + 1) + ": unknown column '" +
                                       fields[i].name + "' (expected time, deformation or force)");
                const auto missing = std::find(picked.begin(), picked.end(), -1) - picked.begin();
                fail(line, std::string("no ") + kColumnNames[missing] +
                               " column in the header (name the columns time, deformation, "
                               "force, or pick them with --columns T,D,F)");
            }
        } else {
            picked = {0, 1, 2};
            m_exactCount = true;
            m_fieldCount = 3;
        }
        if (!fields.empty())
            m_fieldCount = fields.size();
        for (int c = 0; c < 3; ++c) {
            m_position[std::size_t(c)] = std::size_t(picked[std::size_t(c)]);
            if (picked[std::size_t(c)] < int(fields.size())) {
                const HeaderField& f = fields[std::size_t(picked[std::size_t(c)])];
                m_written[std::size_t(c)] = f.unit;
                if (m_options.columns && f.unit.empty())
                    m_written[std::size_t(c)] = f.lastWord; // picked by position: NAME_UNIT
                if (c == Time && f.role && f.role->index && f.unit.empty())
                    m_written[Time] = "step";
            }
        }
        resolveUnits();
    }

    /// Decide the scales from the explicit units or the header's.
    void resolveUnits() {
        if (m_options.units)
            m_written = {m_options.units->time, m_options.units->deformation,
                         m_options.units->force};
        MeasuredDataScales scales;
        try {
            scales =
                measuredDataScales({m_written[Time], m_written[Deformation], m_written[Force]});
        } catch (const MeasuredDataError& e) {
            fail(m_headerLine, e.what());
        }
        m_scale = {scales.time, scales.deformation, scales.force};
        m_history.deformationUnits = scales.deformationUnits;
        m_history.forceUnits = scales.forceUnits;
    }

    void row(const std::vector<std::string>& fields, int line) {
        if (m_fieldCount == 0)
            m_fieldCount = fields.size();
        if (fields.size() != m_fieldCount) {
            std::string what = "expected " + std::to_string(m_fieldCount) + " values (";
            what += m_fieldCount == 3 && m_position == std::array<std::size_t, 3>{0, 1, 2}
                        ? "time, deformation, force"
                        : "as the first row or the header";
            what += "), found " + std::to_string(fields.size());
            if (m_exactCount && fields.size() > 3)
                what += " (pick the time, deformation and force columns with --columns T,D,F "
                        "or name them in a header)";
            fail(line, what);
        }
        std::array<double, 3> v{};
        for (int c = 0; c < 3; ++c) {
            const std::size_t i = m_position[std::size_t(c)];
            if (i >= fields.size())
                fail(line, std::string("no column ") + std::to_string(i + 1) + " (" +
                               kColumnNames[c] + "): the row has " + std::to_string(fields.size()) +
                               " values");
            double x = 0.0;
            if (!parseNumber(fields[i], x))
                fail(line, "column " + std::to_string(i + 1) + " (" + kColumnNames[c] + "): '" +
                               fields[i] + "' is not a number");
            if (!std::isfinite(x))
                fail(line, "column " + std::to_string(i + 1) + " (" + kColumnNames[c] +
                               "): the value is not finite");
            v[std::size_t(c)] = x * m_scale[std::size_t(c)];
        }
        if (!m_history.time.empty() && !(v[Time] > m_history.time.back())) {
            std::ostringstream m;
            m << "time " << v[Time] << " s does not increase (previous " << m_history.time.back()
              << " s)";
            fail(line, m.str());
        }
        m_history.time.push_back(v[Time]);
        m_history.deformation.push_back(v[Deformation]);
        m_history.force.push_back(v[Force]);
    }

    SpecimenHistory read(std::istream& in) {
        m_history.source = m_source;
        std::string text;
        int line = 0;
        bool started = false;
        std::optional<std::string> comment; // a "# columns:" comment's text
        bool headerLine = false;
        int headerAt = 1;
        while (std::getline(in, text)) {
            ++line;
            if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0)
                text.erase(0, 3); // UTF-8 byte order mark
            const std::string t = trim(text);
            if (t.empty())
                continue;
            if (t[0] == '#') {
                if (auto c = commentColumns(t); c && !started) {
                    comment = std::move(c);
                    headerAt = line;
                }
                continue;
            }
            const std::vector<std::string> fields = splitFields(t);
            if (!started) {
                started = true;
                if (!looksNumeric(fields)) {
                    headerLine = true;
                    resolveColumns(fields, line);
                    continue;
                }
            }
            if (m_firstDataLine == 0) {
                m_firstDataLine = line;
                if (!headerLine)
                    resolveColumns(comment ? commentFields(*comment, fields.size())
                                           : std::vector<std::string>{},
                                   comment ? headerAt : line);
            }
            row(fields, line);
        }
        if (in.bad())
            throw MeasuredDataError(m_source + ": cannot be read");
        if (m_history.time.empty())
            throw MeasuredDataError(m_source + ": no data rows (expected lines of time, "
                                               "deformation, force)");
        return std::move(m_history);
    }

private:
    std::string m_source;
    MeasuredDataOptions m_options;
    std::array<std::size_t, 3> m_position{0, 1, 2}; ///< field of time, deformation, force
    std::array<std::string, 3> m_written;
    std::array<double, 3> m_scale{1.0, 1.0, 1.0};
    std::size_t m_fieldCount = 0; ///< values per row (0: decided by the first row)
    bool m_exactCount = false;    ///< no header, no --columns: rows are time, deformation, force
    int m_headerLine = 1;
    int m_firstDataLine = 0;
    SpecimenHistory m_history;
};

std::vector<std::string> commaParts(const std::string& text) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream s(text);
    while (std::getline(s, part, ','))
        parts.push_back(trim(part));
    return parts;
}

} // namespace

MeasuredDataScales measuredDataScales(const MeasuredDataUnits& written) {
    const std::array<std::string, 3> w{written.time, written.deformation, written.force};
    for (int c = 0; c < 3; ++c) {
        if (w[std::size_t(c)].empty())
            fail(std::string("no unit for the ") + kColumnNames[c] +
                 " (write e.g. 'time [s], deformation [mm], force [kN]' in the "
                 "header, or give the units explicitly: --units s,mm,kN)");
    }
    MeasuredDataScales out;
    const std::string& t = w[0];
    if (lower(t) == "step") {
        out.time = 1.0;
    } else if (const auto u = units::parse(t, units::Dimension::Time)) {
        out.time = u->factor;
    } else {
        fail("unknown time unit '" + t + "' (expected " + units::accepted(units::Dimension::Time) +
             ", or step for a sample index)");
    }
    const auto d = units::parseDeformation(w[1]);
    if (!d)
        fail("unknown deformation unit '" + w[1] + "' (expected " +
             units::accepted(units::Dimension::Length) + ", " +
             units::accepted(units::Dimension::Rotation) + ")");
    out.deformation = d->factor;
    const bool rad = d->dimension == units::Dimension::Rotation;
    const std::string& fw = w[2];
    const bool weight = trim(fw) == "g" || trim(fw) == "G";
    const auto f = weight ? std::nullopt : units::parseForce(fw);
    if (!weight && !f)
        fail("unknown force unit '" + fw + "' (expected " + forceUnitsExpected() + ")");
    const bool moment = f && f->dimension == units::Dimension::Moment;
    if (rad && !moment && !weight)
        fail("deformation in " + w[1] + " needs a moment unit (" +
             units::accepted(units::Dimension::Moment) + "), found '" + fw + "'");
    if (!rad && moment)
        fail("deformation in " + w[1] + " needs a force unit (" +
             units::accepted(units::Dimension::Force) + ", g), found the moment unit '" + fw + "'");
    out.force = weight ? 1.0 : f->factor;
    out.deformationUnits = rad ? "rad" : "m";
    out.forceUnits = weight ? "W" : (rad ? "kN m" : "kN");
    return out;
}

MeasuredDataUnits parseMeasuredDataUnits(const std::string& text) {
    const std::vector<std::string> parts = commaParts(text);
    if (parts.size() != 3 || parts[0].empty() || parts[1].empty() || parts[2].empty())
        throw MeasuredDataError("--units: expected three units TIME,DEFORMATION,FORCE, e.g. "
                                "s,mm,kN; found '" +
                                text + "'");
    return {parts[0], parts[1], parts[2]};
}

MeasuredDataColumns parseMeasuredDataColumns(const std::string& text) {
    const std::vector<std::string> parts = commaParts(text);
    std::array<int, 3> v{};
    bool ok = parts.size() == 3;
    for (std::size_t i = 0; ok && i < 3; ++i) {
        const char* b = parts[i].data();
        const char* e = b + parts[i].size();
        const auto r = std::from_chars(b, e, v[i]);
        ok = r.ec == std::errc() && r.ptr == e && v[i] >= 1;
    }
    if (ok && (v[0] == v[1] || v[0] == v[2] || v[1] == v[2]))
        ok = false;
    if (!ok)
        throw MeasuredDataError("--columns: expected three different column numbers "
                                "TIME,DEFORMATION,FORCE counted from 1, e.g. 1,2,3; found '" +
                                text + "'");
    return {v[0], v[1], v[2]};
}

SpecimenHistory readMeasuredDataCsv(std::istream& in, const std::string& source,
                                    const MeasuredDataOptions& options) {
    return Reader(source, options).read(in);
}

SpecimenHistory readMeasuredDataCsv(std::istream& in, const std::string& source,
                                    const std::optional<MeasuredDataUnits>& units) {
    return readMeasuredDataCsv(in, source, MeasuredDataOptions{units, std::nullopt});
}

SpecimenHistory readMeasuredDataCsv(const std::string& path, const MeasuredDataOptions& options) {
    // Bounded before reading: a device (/dev/zero), a pipe or a huge file is refused.
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw MeasuredDataError(path + ": not a regular file (a folder, device, pipe or socket)");
    if (const auto size = std::filesystem::file_size(path, ec);
        !ec && size > limits::kMaxTextFileBytes)
        throw MeasuredDataError(path + ": too large (" + std::to_string(size) + " bytes, at most " +
                                std::to_string(limits::kMaxTextFileBytes) + ")");
    std::ifstream in(path);
    if (!in)
        throw MeasuredDataError(path + ": cannot be opened (no such file or no permission)");
    return readMeasuredDataCsv(in, path, options);
}

SpecimenHistory readMeasuredDataCsv(const std::string& path,
                                    const std::optional<MeasuredDataUnits>& units) {
    return readMeasuredDataCsv(path, MeasuredDataOptions{units, std::nullopt});
}

} // namespace hsmu
