#pragma once
// StepRecord: everything one integration step produced, handed to observers (recorder, plot
// feed, CSV writer, statistics). Vectors are over the *full* DOFs; element entries follow the
// structure's element order. Units: those of the structure (presets: m, s, kN, rad, kN m).

#include "core/experimental/ExperimentalControl.h"
#include "core/updating/ModelUpdater.h"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace hsmu {

struct ElementSample {
    double deformation = 0.0; ///< law deformation (measured for a specimen)
    double force = 0.0;       ///< law force (measured for a specimen)
    /// Commanded deformation for a specimen; NaN for a numerical element.
    double commanded = std::numeric_limits<double>::quiet_NaN();
    /// A specimen's actuator channels as its control reported them with the step's
    /// measurement (ExperimentalControl::actuatorChannels); NaN / -1 where it reports none,
    /// always for a numerical element and at step 0.
    ActuatorChannels actuator{};
};

struct StepRecord {
    int step = 0;                   ///< 0 is the initial state
    double time = 0.0;              ///< [s]
    double groundAcceleration = 0.0; ///< [m/s^2]
    Eigen::VectorXd u, v, a;        ///< DOF displacement [m], velocity [m/s], acceleration [m/s^2]
    std::vector<ElementSample> elements;
    /// Per site (RunLayout::sites order): the step's round trip [s], the slowest of the site's
    /// elements from target sent to measurement received; NaN at step 0.
    std::vector<double> siteRoundTrips;
    /// Every element's channels (ElementChannels.h: each basic DOF and actuator of a multi-DOF
    /// element), elements in structure order, RunLayout::channels' order; empty without
    /// multi-DOF elements.
    std::vector<double> channels;
    bool hasUpdating = false; ///< the test runs online model updating
    UpdatingSample updating;  ///< valid when hasUpdating (step 0: initial estimate)
};

/// Receives every committed step. Called on the thread that runs HybridTest::step().
class StepObserver {
public:
    virtual ~StepObserver() = default;
    virtual void onStep(const StepRecord& record) = 0;
};

} // namespace hsmu
