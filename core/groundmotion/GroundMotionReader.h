#pragma once
// Readers for ground-motion files. Every reader returns a GroundMotion in m/s^2 with sample
// i at t = i dt (first sample at t = 0), name = the file name, source = the path as given.
//
// Formats (docs/ground-motions.md has examples):
//   At2              PEER AT2, 4 header lines then NPTS values in any count per line. Line 4 is
//                    "NPTS=  1559, DT= .02000 SEC" (PEER / Peknold), "NPTS=   5990, DT=   .0050
//                    SEC" (NGA-West2) or "  4000    0.0100    NPTS, DT" (older NGA). Values are
//                    split on blanks; glued Fortran fields (8F10.5 with wide values) are split
//                    by the field width stated in the header ("8F10.5") or seen on the first
//                    data line, else at signs. Units from the header ("UNITS OF G", "(g)",
//                    "cm/s/s", "CM/SEC/SEC", "gal", "m/s/s"), g if none is named.
//   TimeAcceleration two columns "time acceleration" separated by blanks, tabs, ',' or ';';
//                    '#' starts a comment. Time must increase with a uniform step: every step
//                    within 1e-6 (relative) of the mean step. The first time becomes t = 0.
//   SingleColumn     acceleration values in reading order (normally one per line), '#'
//                    comments; dt given by the caller.
//
// Errors: every failure throws GroundMotionError (a std::runtime_error) whose what() names the
// file, the 1-based line where relevant and what was expected, e.g.
// "elcentro.AT2 line 4: expected 'NPTS=..., DT=...' header, found 'xyz'". Empty records,
// non-finite values, dt <= 0, a value count different from NPTS and missing files are errors.

#include "core/groundmotion/AccelerationUnit.h"
#include "core/groundmotion/GroundMotion.h"
#include "core/groundmotion/GroundMotionError.h"

#include <filesystem>
#include <optional>

namespace hsmu {

enum class GroundMotionFormat {
    Auto,             ///< decide from the content (detectGroundMotionFormat)
    At2,              ///< PEER AT2 (three header layouts)
    TimeAcceleration, ///< two columns: time [s], acceleration
    SingleColumn      ///< acceleration values only; needs dt
};

/// PEER AT2. unit overrides the unit named in the header.
GroundMotion readAt2(const std::filesystem::path& path,
                     std::optional<AccelerationUnit> unit = std::nullopt);

/// Two columns: time [s] and acceleration in `unit`.
GroundMotion readTimeAcceleration(const std::filesystem::path& path,
                                  AccelerationUnit unit = AccelerationUnit::G);

/// Acceleration values in `unit` at interval dt [s] (> 0, finite).
GroundMotion readSingleColumn(const std::filesystem::path& path, double dt,
                              AccelerationUnit unit = AccelerationUnit::G);

/// Format by content: At2 if the extension is .at2 (any case) or one of the first 4 lines,
/// not a '#' comment, contains "NPTS"; otherwise by the number of fields on the first data
/// line: 2 -> TimeAcceleration, any other count -> SingleColumn (values in reading order).
/// Throws GroundMotionError for a missing or empty file.
GroundMotionFormat detectGroundMotionFormat(const std::filesystem::path& path);

/// Read any supported file. unit: for At2 overrides the header, for the text formats it is the
/// file's unit (g if not given). dt: required for SingleColumn; for At2 and TimeAcceleration,
/// if given, it must agree with the file's own step (1e-6 relative) or an error is thrown.
GroundMotion readGroundMotion(const std::filesystem::path& path,
                              GroundMotionFormat format = GroundMotionFormat::Auto,
                              std::optional<AccelerationUnit> unit = std::nullopt,
                              std::optional<double> dt = std::nullopt);

} // namespace hsmu
