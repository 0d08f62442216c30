#pragma once
// MeasuredDataCsv: reads the measured history of a specimen from a CSV or text file (an older
// test a lab wants to calibrate from) into a SpecimenHistory in the console's units.
//
// Format (docs/units.md): one sample per line, values separated by commas, semicolons, tabs or
// spaces. Blank lines and lines starting with '#' are skipped. The columns are found so:
//  - a header line (the first line that is not a comment and does not start with a number)
//    names them, in any order, with their units: "time [s], deformation [mm], force [kN]",
//    "t (ms); rotation (rad); moment (kN m)", or NAME_UNIT as in "displacement_mm force_N";
//  - without a header line, a comment "# columns: NAME NAME ..." (case-insensitive) names them
//    the same way (words past the number of values of a row are commentary and ignored);
//  - --columns T,D,F (MeasuredDataColumns) picks them by position, counted from 1: the names
//    are then not used for the roles, only for their units.
// Column names: time | t, or a sample index step | k | index | sample (its values are used as
// times in s: a quasi-static record has no time base); deformation | displacement | rotation |
// d | u; force | moment | load | lateral_load | f (a header naming both a time and a sample
// index uses the time). Other named columns are ignored when a
// header names all three or --columns picks them; without a header and --columns a row must
// have exactly three values time, deformation, force.
// Units (core/util/Units.h; explicit units, the --units option, replace the header's):
//     time         s, ms; step for a sample index (the default of an index column)
//     deformation  m, cm, mm, in, ft (lateral) or rad, mrad, deg (rotation)
//     force        N, kN, MN, lbf, kip, kgf, tonf with a length; a moment (a force unit times a
//                  length unit: "kN m", "kNm", "kip in", "lbf*ft", "N.mm") with a rotation;
//                  g: the load in units of the specimen's weight (as normalized records
//                  give it): the values are kept and labelled "W" (forceUnits).
// Values are converted to s, m or rad, kN or kN m. A column without a unit and no explicit
// units is an error (a number must never be guessed in the wrong unit).
// Errors (MeasuredDataError, "FILE: line L: what"), e.g.
//     "data.csv: line 7: expected 3 values (time, deformation, force), found 2"
//     "data.csv: line 9: column 2 (deformation): 'abc' is not a number"
//     "data.csv: line 12: time 0.3 s does not increase (previous 0.31 s)"
//     "data.csv: line 1: unknown deformation unit 'yd' (expected m, cm, mm, in, ft, rad, mrad,
//      deg)"
// Thread rules: none.

#include "core/offline/SpecimenHistory.h"

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

/// The factors that take each column to the console's units (value * factor) and the units the
/// history is then in: deformationUnits "m" or "rad", forceUnits "kN", "kN m" or "W" (g: the
/// values are kept). The one rule for a file's units and for arrays given with units (the
/// Python module's hsmu.calibrate). Throws MeasuredDataError (no file or line: the caller
/// adds them) for a missing or unknown unit or a deformation / force pair that does not match.
struct MeasuredDataScales {
    double time = 1.0, deformation = 1.0, force = 1.0;
    std::string deformationUnits = "m", forceUnits = "kN";
};
MeasuredDataScales measuredDataScales(const MeasuredDataUnits& units);

/// Parse "s,mm,kN" (the --units option). Throws MeasuredDataError.
MeasuredDataUnits parseMeasuredDataUnits(const std::string& text);

/// 1-based positions of the time (or sample index), deformation and force columns.
struct MeasuredDataColumns {
    int time = 1, deformation = 2, force = 3;
};

/// Parse "1,2,3" (the --columns option): three different numbers >= 1. Throws
/// MeasuredDataError.
MeasuredDataColumns parseMeasuredDataColumns(const std::string& text);

struct MeasuredDataOptions {
    std::optional<MeasuredDataUnits> units;     ///< replace the header's units
    std::optional<MeasuredDataColumns> columns; ///< pick the columns by position
};

/// Read a file. `units` replace the header's. Throws MeasuredDataError.
SpecimenHistory readMeasuredDataCsv(const std::string& path,
                                    const std::optional<MeasuredDataUnits>& units = std::nullopt);
SpecimenHistory readMeasuredDataCsv(const std::string& path, const MeasuredDataOptions& options);
/// Read from a stream; `source` names it in messages.
SpecimenHistory readMeasuredDataCsv(std::istream& in, const std::string& source,
                                    const std::optional<MeasuredDataUnits>& units = std::nullopt);
SpecimenHistory readMeasuredDataCsv(std::istream& in, const std::string& source,
                                    const MeasuredDataOptions& options);

} // namespace hsmu
