#include "core/hysteresis/MaterialDriver.h"

#include "core/hysteresis/HysteresisLaw.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string_view>

namespace hsmu {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && isBlank(s.front())) {
        s.remove_prefix(1);
    }
    while (!s.empty() && isBlank(s.back())) {
        s.remove_suffix(1);
    }
    return s;
}

// Splits on commas when the line has any, otherwise on runs of blanks.
std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> fields;
    if (line.find(',') != std::string_view::npos) {
        std::size_t start = 0;
        while (true) {
            const std::size_t comma = line.find(',', start);
            fields.push_back(trim(line.substr(start, comma - start)));
            if (comma == std::string_view::npos) {
                break;
            }
            start = comma + 1;
        }
        return fields;
    }
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isBlank(line[i])) {
            ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && !isBlank(line[i])) {
            ++i;
        }
        if (i > start) {
            fields.push_back(line.substr(start, i - start));
        }
    }
    return fields;
}

// Locale-independent parse of a whole field as a finite double.
std::optional<double> parseNumber(std::string_view field) {
    if (!field.empty() && field.front() == '+') {
        field.remove_prefix(1);
    }
    if (field.empty()) {
        return std::nullopt;
    }
    double value = 0.0;
    const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (error != std::errc{} || end != field.data() + field.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

// %.17g without the C locale's decimal separator (the GUI process sets LC_NUMERIC).
std::string formatExact(double v) {
    char buffer[40];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, 17);
    return std::string(buffer, result.ptr);
}

[[noreturn]] void fail(const std::string& source, std::size_t lineNumber, const std::string& what) {
    throw std::runtime_error(source + ", line " + std::to_string(lineNumber) + ": " + what);
}

} // namespace

std::vector<double> parseDeformationHistory(std::istream& in, const std::string& sourceName) {
    return parseTimedHistory(in, sourceName).deformation;
}

TimedHistory parseTimedHistory(std::istream& in, const std::string& sourceName) {
    std::vector<double> deformations, times;
    std::size_t columns = 0;
    std::size_t lineNumber = 0;
    std::string raw;
    while (std::getline(in, raw)) {
        ++lineNumber;
        std::string_view line = raw;
        if (lineNumber == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") {
            line.remove_prefix(3);
        }
        line = trim(line);
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const auto fields = splitFields(line);
        if (columns == 0 && !parseNumber(fields.front())) {
            continue; // header line
        }
        if (columns == 0) {
            columns = fields.size();
            if (columns > 2) {
                fail(sourceName, lineNumber,
                     "expected 1 column (deformation) or 2 columns (time, deformation), found " +
                         std::to_string(columns));
            }
        }
        if (fields.size() != columns) {
            fail(sourceName, lineNumber,
                 "expected " + std::to_string(columns) +
                     " column(s) like the first data line, found " + std::to_string(fields.size()));
        }
        for (const auto field : fields) {
            if (!parseNumber(field)) {
                std::string what = "'";
                what.append(field);
                what.append("' is not a finite number");
                fail(sourceName, lineNumber, what);
            }
        }
        deformations.push_back(*parseNumber(fields.back()));
        if (columns == 2) {
            times.push_back(*parseNumber(fields.front()));
        }
    }
    if (in.bad()) {
        throw std::runtime_error(sourceName + ": read error after line " +
                                 std::to_string(lineNumber));
    }
    if (deformations.empty()) {
        throw std::runtime_error(sourceName + ": no deformation data found");
    }
    return {std::move(times), std::move(deformations)};
}

std::vector<double> readDeformationHistory(const std::string& path) {
    return readTimedHistory(path).deformation;
}

TimedHistory readTimedHistory(const std::string& path) {
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error(path + ": cannot open the deformation history file");
    }
    return parseTimedHistory(in, path);
}

void driveLawInto(HysteresisLaw& law, std::span<const double> deformations,
                  std::span<const double> time, std::span<double> force, std::span<double> tangent,
                  const std::function<void(std::size_t)>& afterCommit) {
    const bool rate = law.isRateDependent();
    if (rate && time.size() != deformations.size()) {
        throw std::runtime_error(law.lawName() + " is rate-dependent: the history needs a time "
                                                 "for every point (a time column, or a step)");
    }
    for (std::size_t i = 0; i < deformations.size(); ++i) {
        if (rate) {
            const double dt = historyTimeIncrement(time, i);
            if (!(dt > 0.0)) {
                throw std::runtime_error("the time does not increase at point " +
                                         std::to_string(i) + " (time " + formatExact(time[i]) +
                                         ")");
            }
            law.setTimeIncrement(dt);
        }
        const LawStatus status = law.setTrialDeformation(deformations[i]);
        if (status != LawStatus::Ok) {
            const std::string why = law.failureReason();
            throw std::runtime_error(law.lawName() + ": " + lawStatusName(status) + " at point " +
                                     std::to_string(i) + " (deformation " +
                                     formatExact(deformations[i]) + ")" +
                                     (why.empty() ? "" : ": " + why));
        }
        if (!force.empty())
            force[i] = law.trialForce();
        if (!tangent.empty())
            tangent[i] = law.trialTangent();
        law.commit();
        if (afterCommit)
            afterCommit(i);
    }
}

std::vector<MaterialSample> driveLaw(HysteresisLaw& law, const std::vector<double>& deformations) {
    return driveLaw(law, deformations, {});
}

std::vector<MaterialSample> driveLaw(HysteresisLaw& law, const std::vector<double>& deformations,
                                     const std::vector<double>& time) {
    std::vector<double> force(deformations.size()), tangent(deformations.size());
    driveLawInto(law, deformations, time, force, tangent);
    std::vector<MaterialSample> samples;
    samples.reserve(deformations.size());
    for (std::size_t i = 0; i < deformations.size(); ++i)
        samples.push_back({deformations[i], force[i], tangent[i]});
    return samples;
}

void writeMaterialCsv(std::ostream& out, const std::vector<MaterialSample>& samples) {
    out << "deformation,force,tangent\n";
    for (const MaterialSample& s : samples) {
        out << formatExact(s.deformation) << ',' << formatExact(s.force) << ','
            << formatExact(s.tangent) << '\n';
    }
}

void writeMaterialCsv(const std::string& path, const std::vector<MaterialSample>& samples) {
    std::ofstream out(path);
    if (!out) {
        throw std::runtime_error(path + ": cannot open for writing");
    }
    writeMaterialCsv(out, samples);
    out.flush();
    if (!out) {
        throw std::runtime_error(path + ": write failed");
    }
}

} // namespace hsmu
