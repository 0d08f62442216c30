#pragma once
// PreflightReport: what the operator confirms before a test starts (as OpenFresco's GenericTCP
// control asks before its first step): the integrator and its stability check
// (docs/method.md, Hybrid simulation: explicit Newmark needs omega_max dt <= 2), the ground motion,
// and per specimen its control, its safety limits and the values measured after the control was
// prepared (the zero the test starts from), or, for a specimen loaded by an earlier test, its
// committed steps and last deformation; a multi-actuator specimen's per-actuator limits.
// Units: the specimen's (rad and kN m for a
// rotational spring, m and kN for a lateral one); s; m/s^2.
// Thread rules: plain data; preflightOf() on the thread that runs the test, after prepare().

#include "core/experimental/ActuatorLimitCheck.h"
#include "core/experimental/SafetyLimits.h"
#include "core/integration/StabilityCheck.h"

#include <QMetaType>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace hsmu {
class HybridTest;
}

namespace hsmu::gui {

struct SpecimenPreflight {
    std::string element;
    std::string control; ///< the control's own description (link, virtual, ...)
    std::string deformationUnit; ///< e.g. "rad"
    std::string forceUnit;       ///< e.g. "kN m"
    SafetyLimits limits;
    double measuredDeformation = 0.0; ///< after prepare(); a loaded specimen: lastDeformation
    double measuredForce = 0.0;       ///< after prepare(); NaN: not measured yet (loaded)
    /// Loaded by an earlier test (ExperimentalControl::priorLoading(); docs/console.md,
    /// "A specimen loaded by an earlier test"): its committed steps and last deformation.
    std::uint64_t committedSteps = 0;
    double lastDeformation = 0.0;
    /// Why its controller refused a fresh specimen ("" = not asked, or it gave one).
    std::string freshRefused;
    /// A multi-actuator specimen's per-channel limits against what the run is known to reach
    /// (core/experimental/ActuatorLimitCheck.h); empty for a one-actuator specimen.
    std::vector<ActuatorLimitLine> actuatorLimits;

    bool loaded() const { return committedSteps > 0; }
    /// Continuing would send a first target about |lastDeformation| away from where the
    /// specimen stands (this test starts from rest): more than the increment limit, which the
    /// controller refuses (interlock) before the first step is taken.
    bool continueExceedsIncrement() const {
        const double limit = limits.maxIncrement;
        return loaded() && std::isfinite(limit) && limit > 0.0 && std::abs(lastDeformation) > limit;
    }
};

struct PreflightReport {
    std::string integrator;
    double dt = 0.0; ///< [s]
    int totalSteps = 0;
    StabilityReport stability;
    bool allowUnstable = false; ///< the configuration forces an unstable run
    std::string groundMotion;   ///< the record's name
    double pga = 0.0;           ///< [m/s^2]
    std::vector<SpecimenPreflight> specimens;

    /// The test may start once the operator confirms (stable, or forced by the configuration).
    bool startable() const { return stability.stable || allowUnstable; }
    /// Some specimen was loaded by an earlier test: the operator chooses continue or fresh.
    /// Some actuator's configured limit is below what the run commands (a FAIL line).
    bool hasExceededActuatorLimit() const {
        for (const SpecimenPreflight& s : specimens)
            for (const ActuatorLimitLine& l : s.actuatorLimits)
                if (l.verdict == LimitVerdict::Exceeded)
                    return true;
        return false;
    }
    bool hasLoadedSpecimen() const {
        for (const SpecimenPreflight& s : specimens)
            if (s.loaded())
                return true;
        return false;
    }
};

/// Copy the report out of a prepared test.
PreflightReport preflightOf(const HybridTest& test, bool allowUnstable);

} // namespace hsmu::gui

Q_DECLARE_METATYPE(hsmu::gui::PreflightReport)
