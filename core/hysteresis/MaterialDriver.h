#pragma once
// MaterialDriver: the core of the `hsmu material` command (like OpenSees' uniaxial material
// tester): read a deformation history, drive a HysteresisLaw through it point by point
// (trial + commit), write deformation, force and tangent as CSV.
// Units are the law's: deformations in the law's deformation unit, forces in its force unit.

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

class HysteresisLaw;

/// One evaluated point of a history.
struct MaterialSample {
    double deformation = 0.0; ///< imposed total deformation
    double force = 0.0;       ///< force after the point was committed
    double tangent = 0.0;     ///< tangent dF/du at that point
};

/// Reads a deformation history from a text/CSV file.
/// Format: one column (deformation) or two columns (time, deformation), fields separated by a
/// comma (surrounding blanks allowed) or by spaces/tabs; every data line must have the same
/// number of columns as the first one. Blank lines and lines whose first non-blank character
/// is '#' are skipped anywhere; before the first data line, lines whose first field is not a
/// number are header lines and are skipped. Values must be finite. CRLF endings are accepted.
/// Throws std::runtime_error naming the file and the 1-based line number for malformed
/// content, and naming the file if it cannot be opened or holds no data.
std::vector<double> readDeformationHistory(const std::string& path);

/// Same as readDeformationHistory for an already open stream; sourceName is used in messages.
std::vector<double> parseDeformationHistory(std::istream& in, const std::string& sourceName);

/// A deformation history with its times: `time` empty for a one-column file.
struct TimedHistory {
    std::vector<double> time;        ///< [s] (the first column of a two-column file)
    std::vector<double> deformation; ///< the last column
};

/// readDeformationHistory() keeping the time column of a two-column file.
TimedHistory readTimedHistory(const std::string& path);
/// parseDeformationHistory() keeping the time column of a two-column file.
TimedHistory parseTimedHistory(std::istream& in, const std::string& sourceName);

/// Drives `law` from its current committed state through `deformations`: for each point,
/// setTrialDeformation then commit, and records the trial force and tangent.
/// Throws std::runtime_error naming the 0-based point index (and the deformation) if the law
/// does not return LawStatus::Ok; the law is then left committed at the previous point.
std::vector<MaterialSample> driveLaw(HysteresisLaw& law, const std::vector<double>& deformations);

/// driveLaw() for a history with times: a rate-dependent law (HysteresisLaw.h) gets the time
/// increment historyTimeIncrement(time, i) before point i (the first point is reached
/// quasi-statically, as in every replay of a measured history); the others ignore the times.
/// Throws std::runtime_error if the law is rate-dependent and `time` does not give one time
/// per point, or the times do not increase.
std::vector<MaterialSample> driveLaw(HysteresisLaw& law, const std::vector<double>& deformations,
                                     const std::vector<double>& time);

/// The loop of driveLaw (the one loop; driveLaw and the Python module's Law.drive call it),
/// writing into the caller's arrays: force[i] and tangent[i] for point i (an empty span is not
/// written; a non-empty one has deformations.size() elements); time as driveLaw's (may be
/// empty for a rate-independent law); afterCommit(i), when given, is called once point i is
/// committed (to read state variables such as Bouc-Wen's z).
/// Throws as driveLaw; the points before the failing one are written and committed.
void driveLawInto(HysteresisLaw& law, std::span<const double> deformations,
                  std::span<const double> time, std::span<double> force, std::span<double> tangent,
                  const std::function<void(std::size_t)>& afterCommit = {});

/// Writes the header "deformation,force,tangent" and one line per sample, every value with
/// 17 significant digits like "%.17g" (round-trips exactly), always with a '.' decimal point
/// whatever the C locale.
void writeMaterialCsv(std::ostream& out, const std::vector<MaterialSample>& samples);
/// Same, to a file; throws std::runtime_error naming the file if it cannot be written.
void writeMaterialCsv(const std::string& path, const std::vector<MaterialSample>& samples);

} // namespace hsmu
