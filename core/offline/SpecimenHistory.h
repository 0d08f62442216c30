#pragma once
// SpecimenHistory: the measured response of one specimen, as offline identification
// (OfflineIdentification.h) takes it: from a run record (historyFromRecord) or from an imported
// CSV of an older test (MeasuredDataCsv.h).
//
// Sample k is one committed step: time [s], measured deformation and measured force in the
// specimen's units (a rotational spring: rad and kN m; a lateral spring: m and kN). Samples are
// identified in order, each as one step of the online identifier; the specimen is taken to
// start virgin at zero deformation before sample 0 (as in a run).
// Thread rules: plain data.

#include <string>
#include <vector>

namespace hsmu {

struct RecordData;

struct SpecimenHistory {
    std::string source;                 ///< where it came from (file, element), for messages
    std::vector<double> time;           ///< [s], increasing
    std::vector<double> deformation;    ///< measured, [rad] or [m]
    std::vector<double> force;          ///< measured, [kN m] or [kN]
    std::string deformationUnits = "m"; ///< "rad" or "m"
    std::string forceUnits = "kN";      ///< "kN m" or "kN"

    int size() const { return int(time.size()); }
    /// Mean time step (t_last - t_0) / (N - 1) [s]; 0 with fewer than two samples.
    double meanStep() const;
    /// Empty if usable; else why not: sizes differ, no samples, a value not finite, time
    /// not increasing (the message names the sample index).
    std::string problem() const;
};

/// The measured deformation and force of the experimental element `element` of a record
/// (rows 1 .. N-1: every committed step; row 0, the initial state at rest, is not a
/// measurement): of the basic DOF the record's updating identified on it, if any
/// (core/record/SpecimenColumns.h). Throws std::invalid_argument if the record has no such
/// specimen.
SpecimenHistory historyFromRecord(const RecordData& record, const std::string& element,
                                  const std::string& source);

} // namespace hsmu
