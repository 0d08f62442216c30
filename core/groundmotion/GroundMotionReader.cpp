#include "core/groundmotion/GroundMotionReader.h"
#include "core/groundmotion/GroundMotionText.h"
#include "core/util/InputLimits.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace hsmu {

namespace {

using detail::excerpt;
using detail::formatNumber;
using detail::parseNumber;
using detail::splitFields;
using detail::stripComment;

constexpr double kUniformStepTolerance = 1e-6; // relative, for time columns and given dt

struct Sample {
    int line = 0;
    std::vector<double> values;
};

// Data lines of a text file: comments stripped, blank lines skipped, every field numeric and
// finite, otherwise an error naming the line.
std::vector<Sample> readNumericLines(const detail::TextFile& file) {
    std::vector<Sample> samples;
    for (std::size_t index = 0; index < file.lines.size(); ++index) {
        const int lineNumber = static_cast<int>(index + 1);
        const auto fields = splitFields(stripComment(file.lines[index]), detail::kTextSeparators);
        if (fields.empty())
            continue;
        Sample sample{lineNumber, {}};
        for (std::string_view field : fields) {
            double value = 0.0;
            if (!parseNumber(field, value))
                throw GroundMotionError(file.name, lineNumber,
                                        "expected a number, found " + excerpt(field));
            if (!std::isfinite(value))
                throw GroundMotionError(file.name, lineNumber,
                                        "non-finite value " + excerpt(field));
            sample.values.push_back(value);
        }
        samples.push_back(std::move(sample));
    }
    if (samples.empty()) {
        const bool blank = std::all_of(file.lines.begin(), file.lines.end(),
                                       [](const std::string& l) { return l.empty(); });
        throw GroundMotionError(file.name, 0,
                                blank ? "the file is empty (no acceleration values)"
                                      : "no data lines (only comments or blank lines)");
    }
    return samples;
}

void checkDt(const std::string& name, double dt) {
    if (!(std::isfinite(dt) && dt > 0.0))
        throw GroundMotionError(name, 0, "the time step dt must be > 0 s, got " + formatNumber(dt));
    if (dt < limits::kMinDt || dt > limits::kMaxDt)
        throw GroundMotionError(name, 0,
                                "the time step dt = " + formatNumber(dt) + " s is outside [" +
                                    formatNumber(limits::kMinDt) + ", " +
                                    formatNumber(limits::kMaxDt) + "] s");
}

bool sameStep(double a, double b) {
    return std::abs(a - b) <= kUniformStepTolerance * b;
}

} // namespace

GroundMotion readTimeAcceleration(const std::filesystem::path& path, AccelerationUnit unit) {
    const detail::TextFile file = detail::readTextFile(path);
    const std::vector<Sample> samples = readNumericLines(file);
    for (const Sample& s : samples) {
        if (s.values.size() != 2)
            throw GroundMotionError(file.name, s.line,
                                    "expected two columns (time, acceleration), found " +
                                        std::to_string(s.values.size()) + " value(s)");
    }
    if (samples.size() < 2)
        throw GroundMotionError(file.name, samples.front().line,
                                "only one sample: the time step cannot be determined");

    const std::size_t n = samples.size();
    const double t0 = samples.front().values[0];
    const double dt = (samples.back().values[0] - t0) / static_cast<double>(n - 1);
    // Report the step that deviates most: with one bad step the mean is off a little, and the
    // first step outside tolerance would otherwise point at the wrong line.
    std::size_t worst = 0;
    double worstDeviation = -1.0;
    for (std::size_t i = 1; i < n; ++i) {
        const double step = samples[i].values[0] - samples[i - 1].values[0];
        if (!(step > 0.0))
            throw GroundMotionError(file.name, samples[i].line,
                                    "time must increase: " + formatNumber(samples[i].values[0]) +
                                        " s follows " + formatNumber(samples[i - 1].values[0]) +
                                        " s");
        const double deviation = std::abs(step - dt);
        if (deviation > worstDeviation) {
            worstDeviation = deviation;
            worst = i;
        }
    }
    if (!sameStep(dt + worstDeviation, dt)) {
        const double step = samples[worst].values[0] - samples[worst - 1].values[0];
        throw GroundMotionError(file.name, samples[worst].line,
                                "non-uniform time step: " + formatNumber(samples[worst].values[0]) +
                                    " s follows " + formatNumber(samples[worst - 1].values[0]) +
                                    " s (step " + formatNumber(step) + " s, mean step " +
                                    formatNumber(dt) +
                                    " s); a uniform step is required (tolerance 1e-6 relative)");
    }

    checkDt(file.name, dt);
    GroundMotion motion;
    motion.name = file.name;
    motion.source = file.source;
    motion.dt = dt;
    const double factor = toMetersPerSecond2(unit);
    motion.acceleration.reserve(n);
    for (const Sample& s : samples)
        motion.acceleration.push_back(s.values[1] * factor);
    return motion;
}

GroundMotion readSingleColumn(const std::filesystem::path& path, double dt, AccelerationUnit unit) {
    const detail::TextFile file = detail::readTextFile(path);
    checkDt(file.name, dt);
    const std::vector<Sample> samples = readNumericLines(file);
    GroundMotion motion;
    motion.name = file.name;
    motion.source = file.source;
    motion.dt = dt;
    const double factor = toMetersPerSecond2(unit);
    for (const Sample& s : samples) {
        for (double value : s.values)
            motion.acceleration.push_back(value * factor);
    }
    return motion;
}

GroundMotionFormat detectGroundMotionFormat(const std::filesystem::path& path) {
    const detail::TextFile file = detail::readTextFile(path);
    if (detail::toUpper(path.extension().string()) == ".AT2")
        return GroundMotionFormat::At2;
    const std::size_t headerLines = std::min<std::size_t>(4, file.lines.size());
    for (std::size_t i = 0; i < headerLines; ++i) {
        const std::string& line = file.lines[i];
        const std::size_t first = line.find_first_not_of(detail::kBlanks);
        const bool comment = first != std::string::npos && line[first] == '#';
        if (!comment && detail::toUpper(line).find("NPTS") != std::string::npos)
            return GroundMotionFormat::At2;
    }
    for (const std::string& line : file.lines) {
        const auto fields = splitFields(stripComment(line), detail::kTextSeparators);
        if (fields.empty())
            continue;
        return fields.size() == 2 ? GroundMotionFormat::TimeAcceleration
                                  : GroundMotionFormat::SingleColumn;
    }
    const bool blank = std::all_of(file.lines.begin(), file.lines.end(),
                                   [](const std::string& l) { return l.empty(); });
    throw GroundMotionError(file.name, 0,
                            std::string(blank ? "the file is empty" : "no data lines") +
                                ": expected an AT2 header ('NPTS=..., DT=...' on line 4), two "
                                "columns (time, acceleration) or one column of values");
}

GroundMotion readGroundMotion(const std::filesystem::path& path, GroundMotionFormat format,
                              std::optional<AccelerationUnit> unit, std::optional<double> dt) {
    if (format == GroundMotionFormat::Auto)
        format = detectGroundMotionFormat(path);
    const std::string name = path.filename().string();
    if (dt)
        checkDt(name, *dt);

    GroundMotion motion;
    switch (format) {
    case GroundMotionFormat::At2:
        motion = readAt2(path, unit);
        break;
    case GroundMotionFormat::TimeAcceleration:
        motion = readTimeAcceleration(path, unit.value_or(AccelerationUnit::G));
        break;
    case GroundMotionFormat::SingleColumn:
    case GroundMotionFormat::Auto:
        if (!dt)
            throw GroundMotionError(name, 0,
                                    "a single column of acceleration values needs the time step "
                                    "dt, and none was given");
        return readSingleColumn(path, *dt, unit.value_or(AccelerationUnit::G));
    }
    if (dt && !sameStep(motion.dt, *dt))
        throw GroundMotionError(name, 0,
                                "the given dt = " + formatNumber(*dt) +
                                    " s disagrees with the file's time step " +
                                    formatNumber(motion.dt) + " s");
    return motion;
}

} // namespace hsmu
