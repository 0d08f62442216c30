#pragma once
// OffsetCheck: the online source of the twins' offsets (docs/method.md, "Offsets", Online).
// It keeps the specimen's measured history (deformation, force, in the specimen's units)
// and, on a worker (ScheduledJob.h), calibrates the updating's law to it with offsets
// (calibrateHistory, CalibrationDefaults.h "Offsets": the branch-counted criterion with
// offsets auto, always with on) each time the history reaches kFirstSamples, then twice
// the size of the last check. A check whose fit keeps the offsets becomes an
// OffsetProposal: the deformation offset u0 and the force offset F0 (OffsetLaw.h) with
// their standard deviations, which supersedes the one still pending. It is never applied
// here: ModelUpdater::approveOffsets() applies it when the operator approves, whatever the
// reporter's policy or the headless approval flag.
// The result of a check is taken at the step ScheduledJob fixes when it starts, so a
// proposal depends on the samples only (waiting for the worker if needed).
// Thread rules: every member from the stepping thread (the job reads its own copy).

#include "core/identification/CalibrationDefaults.h"
#include "core/updating/ScheduledJob.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace hsmu {

/// Offsets offered to the twins, in the specimen's deformation and force units.
struct OffsetProposal {
    int id = 0;
    int step = 0;      ///< the step it was made at
    double time = 0.0; ///< its test time [s]
    double deformationOffset = 0.0; ///< u0 [deformation units]
    double forceOffset = 0.0;       ///< F0 [force units]
    /// Standard deviations (NaN: the value sits on its box, no interval); the 95 % interval
    /// is +-1.96 sd (Calibration.h, statistics).
    double deformationSd = 0.0, forceSd = 0.0;
    double nrmseWithout = 0.0, nrmseWith = 0.0; ///< the two fits' NRMSE [-]
    int branches = 0;      ///< N_eff of the criterion
    double criterion = 0.0; ///< < 0: the data ask for the offsets
    std::size_t samples = 0; ///< the history the check calibrated
};

class OffsetCheck {
public:
    static constexpr std::size_t kFirstSamples = 400;

    /// law: the updating's law (a LawFactory name with calibration defaults); mode: Auto
    /// (propose when the criterion keeps the offsets) or On (propose every check's offsets).
    /// Throws std::invalid_argument for mode Off. A law without calibration defaults makes
    /// no proposal (lastMessage() says why).
    OffsetCheck(std::string law, CalibrationOffsets mode);

    /// One committed step of the specimen (physical units; t: the sample's time [s], for a
    /// rate-dependent law). Returns true when a new proposal was made at this step.
    bool observe(int step, double time, double deformation, double force);

    const std::optional<OffsetProposal>& pending() const { return m_pending; }
    /// Removes the pending proposal `id` and returns it; nullopt if it is not the pending one.
    std::optional<OffsetProposal> take(int id);
    CalibrationOffsets mode() const { return m_mode; }
    const std::string& law() const { return m_law; }
    int checksStarted() const { return m_job.started(); }
    /// Why the last check made no proposal ("" when it did or none ended yet).
    const std::string& lastMessage() const { return m_message; }

private:
    std::string m_law;
    CalibrationOffsets m_mode;
    std::vector<double> m_u, m_f, m_t;
    std::size_t m_next = kFirstSamples;
    ScheduledJob<int, CalibrationResult> m_job;
    std::optional<OffsetProposal> m_pending;
    int m_nextId = 1;
    std::string m_message;
};

} // namespace hsmu
