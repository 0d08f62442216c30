// readAt2: the PEER AT2 reader declared in GroundMotionReader.h.
#include "core/groundmotion/GroundMotionReader.h"
#include "core/groundmotion/GroundMotionText.h"
#include "core/util/InputLimits.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace hsmu {

namespace {

using detail::excerpt;
using detail::formatNumber;
using detail::kBlanks;
using detail::parseNumber;
using detail::splitFields;

constexpr std::size_t kHeaderLines = 4;

struct At2Header {
    double npts = 0.0;
    double dt = 0.0;
    std::string nptsText;
    std::string dtText;
};

bool isAlpha(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// A number followed only by letters ("SEC"), as written after "DT=".
bool parseLeadingNumber(std::string_view token, double& value) {
    std::size_t end = token.size();
    while (end > 0 && isAlpha(token[end - 1]))
        --end;
    return end > 0 && parseNumber(token.substr(0, end), value);
}

// The token after "KEY =" (or "KEY:") in an upper-case line; empty if the key is absent.
std::string_view valueAfterKey(std::string_view upper, std::string_view key) {
    std::size_t pos = upper.find(key);
    if (pos == std::string_view::npos)
        return {};
    pos = upper.find_first_not_of(kBlanks, pos + key.size());
    if (pos == std::string_view::npos || (upper[pos] != '=' && upper[pos] != ':'))
        return {};
    pos = upper.find_first_not_of(kBlanks, pos + 1);
    if (pos == std::string_view::npos)
        return {};
    const std::size_t end = upper.find_first_of(" \t,;", pos);
    return upper.substr(pos, end == std::string_view::npos ? upper.size() - pos : end - pos);
}

bool parseHeaderLine(const std::string& line, At2Header& header) {
    const std::string upper = detail::toUpper(line);
    // PEER / Peknold and NGA-West2: "NPTS=  1559, DT= .02000 SEC".
    const std::string_view npts = valueAfterKey(upper, "NPTS");
    const std::string_view dt = valueAfterKey(upper, "DT");
    if (!npts.empty() && !dt.empty()) {
        header.nptsText = std::string(npts);
        header.dtText = std::string(dt);
        return parseNumber(npts, header.npts) && parseLeadingNumber(dt, header.dt);
    }
    // Older NGA: "  4000    0.0100    NPTS, DT".
    const auto fields = splitFields(upper, " \t,;");
    if (fields.size() >= 4 && fields[2] == "NPTS" && fields[3] == "DT") {
        header.nptsText = std::string(fields[0]);
        header.dtText = std::string(fields[1]);
        return parseNumber(fields[0], header.npts) && parseLeadingNumber(fields[1], header.dt);
    }
    return false;
}

bool containsAny(const std::string& text, std::initializer_list<std::string_view> needles) {
    for (std::string_view needle : needles) {
        std::size_t pos = text.find(needle);
        while (pos != std::string::npos) {
            const bool startsWord = pos == 0 || !isAlpha(text[pos - 1]);
            const std::size_t after = pos + needle.size();
            const bool endsWord = after >= text.size() || !isAlpha(text[after]);
            if (startsWord && endsWord)
                return true;
            pos = text.find(needle, pos + 1);
        }
    }
    return false;
}

// Unit named in the header text (upper case); g unless cm or m per s^2 is named.
AccelerationUnit headerUnit(const std::string& upper) {
    if (containsAny(upper, {"CM/S/S", "CM/SEC/SEC", "CM/S^2", "CM/S2", "CM/S**2", "CM/SEC^2",
                            "CM/SEC2", "CM/SEC**2", "GAL", "GALS"}))
        return AccelerationUnit::CentimetersPerSecond2;
    if (containsAny(upper, {"M/S/S", "M/SEC/SEC", "M/S^2", "M/S2", "M/S**2", "M/SEC^2", "M/SEC2",
                            "M/SEC**2"}))
        return AccelerationUnit::MetersPerSecond2;
    return AccelerationUnit::G;
}

// Field width of a Fortran edit descriptor in the header ("8F10.5" -> 10); 0 if none.
std::size_t headerFieldWidth(const std::string& upper) {
    for (std::size_t i = 0; i + 3 < upper.size(); ++i) {
        const char c = upper[i];
        if (c != 'F' && c != 'E' && c != 'G')
            continue;
        if (i > 0 && isAlpha(upper[i - 1]))
            continue;
        std::size_t j = i + 1;
        std::size_t width = 0;
        while (j < upper.size() && isDigit(upper[j]))
            width = width * 10 + static_cast<std::size_t>(upper[j++] - '0');
        if (width > 0 && j + 1 < upper.size() && upper[j] == '.' && isDigit(upper[j + 1]))
            return width;
    }
    return 0;
}

// Width w if the fields of a cleanly split line end exactly at w, 2w, ... (right-aligned).
std::size_t inferredFieldWidth(std::string_view line, const std::vector<std::string_view>& fields) {
    if (fields.empty())
        return 0;
    const auto end = [&](std::size_t i) {
        return static_cast<std::size_t>(fields[i].data() - line.data()) + fields[i].size();
    };
    const std::size_t width = end(0);
    for (std::size_t i = 1; i < fields.size(); ++i) {
        if (end(i) != (i + 1) * width)
            return 0;
    }
    return width;
}

bool parseFields(const std::vector<std::string_view>& fields, std::vector<double>& out) {
    out.clear();
    for (std::string_view field : fields) {
        double value = 0.0;
        if (!parseNumber(field, value))
            return false;
        out.push_back(value);
    }
    return true;
}

bool parseFixedWidth(std::string_view line, std::size_t width, std::vector<double>& out) {
    std::vector<std::string_view> fields;
    bool blankSeen = false;
    for (std::size_t pos = 0; pos < line.size(); pos += width) {
        const std::string_view chunk = line.substr(pos, width);
        const std::size_t begin = chunk.find_first_not_of(kBlanks);
        if (begin == std::string_view::npos) {
            blankSeen = true;
            continue;
        }
        if (blankSeen)
            return false;
        const std::size_t last = chunk.find_last_not_of(kBlanks);
        fields.push_back(chunk.substr(begin, last - begin + 1));
    }
    return parseFields(fields, out);
}

// Split glued fields such as "-0.12345-0.54321" at signs that do not follow an exponent letter.
bool parseGluedAtSigns(const std::vector<std::string_view>& fields, std::vector<double>& out) {
    std::vector<std::string_view> pieces;
    for (std::string_view field : fields) {
        std::size_t start = 0;
        for (std::size_t i = 1; i < field.size(); ++i) {
            const char prev =
                static_cast<char>(std::toupper(static_cast<unsigned char>(field[i - 1])));
            if ((field[i] == '-' || field[i] == '+') && prev != 'E' && prev != 'D') {
                pieces.push_back(field.substr(start, i - start));
                start = i;
            }
        }
        pieces.push_back(field.substr(start));
    }
    return parseFields(pieces, out);
}

std::string_view firstBadField(const std::vector<std::string_view>& fields) {
    for (std::string_view field : fields) {
        double value = 0.0;
        if (!parseNumber(field, value))
            return field;
    }
    return fields.empty() ? std::string_view() : fields.front();
}

} // namespace

GroundMotion readAt2(const std::filesystem::path& path, std::optional<AccelerationUnit> unit) {
    const detail::TextFile file = detail::readTextFile(path);
    const std::string& name = file.name;
    const auto& lines = file.lines;
    if (lines.empty())
        throw GroundMotionError(name, 0, "the file is empty (expected a PEER AT2 record)");
    if (lines.size() < kHeaderLines)
        throw GroundMotionError(name, 0,
                                "expected 4 header lines with 'NPTS=..., DT=...' on line 4, but "
                                "the file has only " +
                                    std::to_string(lines.size()) + " line(s)");

    At2Header header;
    if (!parseHeaderLine(lines[3], header))
        throw GroundMotionError(name, 4,
                                "expected 'NPTS=..., DT=...' header (or 'n dt NPTS, DT'), found " +
                                    excerpt(lines[3]));
    if (!(header.npts >= 1.0 && header.npts <= 1e9 && std::floor(header.npts) == header.npts))
        throw GroundMotionError(
            name, 4, "NPTS must be a positive whole number, found " + excerpt(header.nptsText));
    if (!(std::isfinite(header.dt) && header.dt > 0.0))
        throw GroundMotionError(name, 4,
                                "DT must be a time step > 0 s, found " + excerpt(header.dtText));
    if (header.dt < limits::kMinDt || header.dt > limits::kMaxDt)
        throw GroundMotionError(name, 4,
                                "DT = " + excerpt(header.dtText) + " s is outside [" +
                                    detail::formatNumber(limits::kMinDt) + ", " +
                                    detail::formatNumber(limits::kMaxDt) + "] s");
    const auto npts = static_cast<std::size_t>(header.npts);

    const std::string upperHeader =
        detail::toUpper(lines[0] + "\n" + lines[1] + "\n" + lines[2] + "\n" + lines[3]);
    std::size_t width = headerFieldWidth(upperHeader);
    const double factor = toMetersPerSecond2(unit.value_or(headerUnit(upperHeader)));

    GroundMotion motion;
    motion.name = name;
    motion.source = file.source;
    motion.dt = header.dt;
    // The header's count is not trusted for the allocation: a few bytes of header may claim
    // 10^9 points (a fuzzer's finding, issue 26). Each value takes at least 2 bytes of text.
    std::size_t dataBytes = 0;
    for (std::size_t index = kHeaderLines; index < lines.size(); ++index)
        dataBytes += lines[index].size() + 1;
    motion.acceleration.reserve(std::min(npts, dataBytes / 2 + 1));
    std::vector<double> values;
    for (std::size_t index = kHeaderLines; index < lines.size(); ++index) {
        const int lineNumber = static_cast<int>(index + 1);
        const std::string_view line = lines[index];
        const auto fields = splitFields(line, kBlanks);
        if (fields.empty())
            continue;
        if (parseFields(fields, values)) {
            if (width == 0)
                width = inferredFieldWidth(line, fields);
        } else if (!(width > 0 && parseFixedWidth(line, width, values)) &&
                   !parseGluedAtSigns(fields, values)) {
            throw GroundMotionError(name, lineNumber,
                                    "expected a number, found " + excerpt(firstBadField(fields)));
        }
        for (double value : values) {
            if (!std::isfinite(value))
                throw GroundMotionError(name, lineNumber,
                                        "non-finite value " + formatNumber(value));
            if (motion.acceleration.size() == npts)
                throw GroundMotionError(name, lineNumber,
                                        "more values than NPTS = " + std::to_string(npts) +
                                            " announced on line 4 (extra value " +
                                            formatNumber(value) + ")");
            motion.acceleration.push_back(value * factor);
        }
    }
    if (motion.acceleration.size() < npts)
        throw GroundMotionError(name, 0,
                                "NPTS = " + std::to_string(npts) + " on line 4 but only " +
                                    std::to_string(motion.acceleration.size()) +
                                    " values follow (the file ends at line " +
                                    std::to_string(lines.size()) + ")");
    return motion;
}

} // namespace hsmu
