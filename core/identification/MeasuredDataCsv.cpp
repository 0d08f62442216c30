#include "core/identification/MeasuredDataCsv.h"
#include "core/util/InputLimits.h"

#include <filesystem>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace hsmu {

namespace {

enum Column { Time = 0, Deformation = 1, Force = 2 };
const char* const kColumnNames[] = {"time", "deformation", "force"};

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

/// A unit as written, without spaces, '*', '.' or the middle dot, lower case ("kN m" -> "knm").
std::string unitKey(const std::string& unit) {
    std::string k;
    for (std::size_t i = 0; i < unit.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(unit[i]);
        if (c == 0xC2 && i + 1 < unit.size() && static_cast<unsigned char>(unit[i + 1]) == 0xB7) {
            ++i; // U+00B7 middle dot
            continue;
        }
        if (c != ' ' && c != '*' && c != '.' && c != '\t')
            k.push_back(char(std::tolower(c)));
    }
    return k;
}

struct Scale {
    double factor = 1.0;
    bool rotation = false; ///< deformation: rad; force: a moment
};

const std::map<std::string, Scale>& units(Column c) {
    static const std::map<std::string, Scale> time{{"s", {1.0}}, {"ms", {1e-3}}};
    static const std::map<std::string, Scale> deformation{
        {"m", {1.0}}, {"mm", {1e-3}}, {"cm", {1e-2}}, {"rad", {1.0, true}}, {"mrad", {1e-3, true}}};
    static const std::map<std::string, Scale> force{
        {"kn", {1.0}},        {"n", {1e-3}},          {"mn", {1e3}},         {"knm", {1.0, true}},
        {"nm", {1e-3, true}}, {"knmm", {1e-3, true}}, {"nmm", {1e-6, true}}, {"mnm", {1e3, true}}};
    return c == Time ? time : (c == Deformation ? deformation : force);
}

const char* expectedUnits(Column c) {
    return c == Time
               ? "s, ms"
               : (c == Deformation ? "m, mm, cm, rad, mrad" : "kN, N, MN, kNm, Nm, kNmm, Nmm");
}

std::optional<Column> columnOf(const std::string& name) {
    static const std::map<std::string, Column> names{{"time", Time},
                                                     {"t", Time},
                                                     {"deformation", Deformation},
                                                     {"displacement", Deformation},
                                                     {"rotation", Deformation},
                                                     {"d", Deformation},
                                                     {"u", Deformation},
                                                     {"force", Force},
                                                     {"moment", Force},
                                                     {"f", Force}};
    auto it = names.find(lower(name));
    return it == names.end() ? std::nullopt : std::optional<Column>(it->second);
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

class Reader {
public:
    Reader(std::string source, const std::optional<MeasuredDataUnits>& given)
        : m_source(std::move(source)), m_given(given) {}

    [[noreturn]] void fail(int line, const std::string& what) const {
        throw MeasuredDataError(m_source + ": line " + std::to_string(line) + ": " + what);
    }

    /// A header line: column order and units as written (may be empty).
    void header(const std::vector<std::string>& fields, int line) {
        if (fields.size() != 3)
            fail(line, "expected a header of 3 columns (time, deformation, force), found " +
                           std::to_string(fields.size()));
        std::array<bool, 3> seen{};
        for (std::size_t i = 0; i < 3; ++i) {
            std::string name = fields[i], unit;
            const auto open = name.find_first_of("[(");
            if (open != std::string::npos) {
                const auto close = name.find_first_of("])", open);
                if (close == std::string::npos)
                    fail(line, "column " + std::to_string(i + 1) + ": unclosed unit in '" +
                                   fields[i] + "'");
                unit = trim(name.substr(open + 1, close - open - 1));
                name = trim(name.substr(0, open));
            }
            const auto c = columnOf(name);
            if (!c)
                fail(line, "column " + std::to_string(i + 1) + ": unknown column '" + name +
                               "' (expected time, deformation or force)");
            if (seen[*c])
                fail(line, "column " + std::to_string(i + 1) + ": '" + name + "' names the " +
                               kColumnNames[*c] + " a second time");
            seen[*c] = true;
            m_order[i] = *c;
            m_written[*c] = unit;
        }
        m_headerLine = line;
    }

    /// Decide the scales from the explicit units or the header's.
    void resolveUnits() {
        const int line = m_headerLine;
        if (m_given) {
            m_written = {m_given->time, m_given->deformation, m_given->force};
        }
        for (int c = 0; c < 3; ++c) {
            const std::string& u = m_written[std::size_t(c)];
            if (u.empty())
                fail(line, std::string("no unit for the ") + kColumnNames[c] +
                               " (write e.g. 'time [s], deformation [mm], force [kN]' in the "
                               "header, or give the units explicitly: --units s,mm,kN)");
            const auto& table = units(Column(c));
            const auto it = table.find(unitKey(u));
            if (it == table.end())
                fail(line, std::string("unknown ") + kColumnNames[c] + " unit '" + u +
                               "' (expected " + expectedUnits(Column(c)) + ")");
            m_scale[std::size_t(c)] = it->second;
        }
        const bool rad = m_scale[Deformation].rotation, moment = m_scale[Force].rotation;
        if (rad && !moment)
            fail(line, "deformation in " + m_written[Deformation] +
                           " needs a moment unit (kNm, Nm, kNmm, Nmm), found '" + m_written[Force] +
                           "'");
        if (!rad && moment)
            fail(line, "deformation in " + m_written[Deformation] +
                           " needs a force unit (kN, N, MN), found the moment unit '" +
                           m_written[Force] + "'");
        m_history.deformationUnits = rad ? "rad" : "m";
        m_history.forceUnits = rad ? "kN m" : "kN";
    }

    void row(const std::vector<std::string>& fields, int line) {
        if (fields.size() != 3)
            fail(line, "expected 3 values (time, deformation, force), found " +
                           std::to_string(fields.size()));
        std::array<double, 3> v{};
        for (std::size_t i = 0; i < 3; ++i) {
            const Column c = m_order[i];
            double x = 0.0;
            if (!parseNumber(fields[i], x))
                fail(line, "column " + std::to_string(i + 1) + " (" + kColumnNames[c] + "): '" +
                               fields[i] + "' is not a number");
            if (!std::isfinite(x))
                fail(line, "column " + std::to_string(i + 1) + " (" + kColumnNames[c] +
                               "): the value is not finite");
            v[c] = x * m_scale[c].factor;
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
        while (std::getline(in, text)) {
            ++line;
            if (line == 1 && text.rfind("\xEF\xBB\xBF", 0) == 0)
                text.erase(0, 3); // UTF-8 byte order mark
            const std::string t = trim(text);
            if (t.empty() || t[0] == '#')
                continue;
            const std::vector<std::string> fields = splitFields(t);
            if (!started) {
                started = true;
                if (!looksNumeric(fields)) {
                    header(fields, line);
                    resolveUnits();
                    continue;
                }
                m_headerLine = line;
                resolveUnits();
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
    std::optional<MeasuredDataUnits> m_given;
    std::array<Column, 3> m_order{Time, Deformation, Force};
    std::array<std::string, 3> m_written;
    std::array<Scale, 3> m_scale;
    int m_headerLine = 1;
    SpecimenHistory m_history;
};

} // namespace

MeasuredDataUnits parseMeasuredDataUnits(const std::string& text) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream s(text);
    while (std::getline(s, part, ','))
        parts.push_back(trim(part));
    if (parts.size() != 3 || parts[0].empty() || parts[1].empty() || parts[2].empty())
        throw MeasuredDataError("--units: expected three units TIME,DEFORMATION,FORCE, e.g. "
                                "s,mm,kN; found '" +
                                text + "'");
    return {parts[0], parts[1], parts[2]};
}

SpecimenHistory readMeasuredDataCsv(std::istream& in, const std::string& source,
                                    const std::optional<MeasuredDataUnits>& units) {
    return Reader(source, units).read(in);
}

SpecimenHistory readMeasuredDataCsv(const std::string& path,
                                    const std::optional<MeasuredDataUnits>& units) {
    // Bounded before reading: a device (/dev/zero), a pipe or a huge file is refused.
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw MeasuredDataError(path + ": not a regular file (a folder, device, pipe or socket)");
    if (const auto size = std::filesystem::file_size(path, ec);
        !ec && size > limits::kMaxTextFileBytes)
        throw MeasuredDataError(path + ": too large (" + std::to_string(size) +
                                " bytes, at most " + std::to_string(limits::kMaxTextFileBytes) +
                                ")");
    std::ifstream in(path);
    if (!in)
        throw MeasuredDataError(path + ": cannot be opened (no such file or no permission)");
    return readMeasuredDataCsv(in, path, units);
}

} // namespace hsmu
