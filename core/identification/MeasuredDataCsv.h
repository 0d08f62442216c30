#pragma once
// MeasuredDataCsv: reads the measured history of a specimen from a CSV file (an older test a
// lab wants to calibrate from) into a SpecimenHistory in the console's units.
//
// Format: one sample per line, three columns time, deformation, force, separated by commas,
// semicolons, tabs or spaces. Blank lines and lines starting with '#' are skipped. An optional
// header line names the columns (any order; case-insensitive) with their units in brackets or
// parentheses:
//     time [s], deformation [mm], force [kN]
//     t (ms); rotation (rad); moment (kNm)
// Column names: time | t; deformation | displacement | rotation | d | u; force | moment | f.
// Units (explicit units, e.g. the --units option, replace the header's):
//     time         s, ms
//     deformation  m, mm, cm (lateral) or rad, mrad (rotation)
//     force        kN, N, MN (with m / mm / cm) or kNm, Nm, kNmm, Nmm (also "kN m", "kN*m",
//                  "kN.m") with rad / mrad
// Values are converted to s, m or rad, kN or kN m. A header without units and no explicit
// units is an error (a number must never be guessed in the wrong unit); without a header
// the columns are time, deformation, force in that order and explicit units are required.
// Errors (MeasuredDataError, "FILE: line L: what"), e.g.
//     "data.csv: line 7: expected 3 values (time, deformation, force), found 2"
//     "data.csv: line 9: column 2 (deformation): 'abc' is not a number"
//     "data.csv: line 12: time 0.3 s does not increase (previous 0.31 s)"
//     "data.csv: line 1: unknown deformation unit 'in' (expected m, mm, cm, rad, mrad)"
//     "data.csv: line 1: deformation in rad needs a moment unit (kNm, Nm, kNmm, Nmm), found 'kN'"
// Thread rules: none.

#include "core/identification/SpecimenHistory.h"

#include <istream>
#include <optional>
#include <stdexcept>
#include <string>

namespace hsmu {

class MeasuredDataError : public std::runtime_error {
public:
    explicit MeasuredDataError(const std::string& message) : std::runtime_error(message) {}
};

/// Units of the three columns as written, e.g. {"s", "mm", "kN"}.
struct MeasuredDataUnits {
    std::string time, deformation, force;
};

/// Parse "s,mm,kN" (the --units option). Throws MeasuredDataError.
MeasuredDataUnits parseMeasuredDataUnits(const std::string& text);

/// Read a file. `units` replace the header's. Throws MeasuredDataError.
SpecimenHistory readMeasuredDataCsv(const std::string& path,
                                    const std::optional<MeasuredDataUnits>& units = std::nullopt);
/// Read from a stream; `source` names it in messages.
SpecimenHistory readMeasuredDataCsv(std::istream& in, const std::string& source,
                                    const std::optional<MeasuredDataUnits>& units = std::nullopt);

} // namespace hsmu
