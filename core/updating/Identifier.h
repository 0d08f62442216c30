#pragma once
// Identifier: parameter identification of one specimen's law from its measured response
// (docs/method.md, The four modules and The paper's UKF). Implementations: UkfIdentifier,
// RobustUkfIdentifier and PinchingUkfIdentifier (every step) and NelderMeadIdentifier (over
// the stored history, when the Inspector asks).
// Values are in the law's own units (normalized for Bouc-Wen with uRef/fRef).

#include "core/identification/ParameterLayout.h"
#include "core/identification/ParameterSet.h"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

struct IdentificationStatus {
    bool ok = true;       ///< false: this step's update was rejected (estimate kept)
    bool updated = false; ///< the estimate changed at this step
    bool refit = false;   ///< a batch fit over the whole history (replay dependent models)
    std::string message;  ///< why, when !ok; what ran, when informative
    /// false: the estimate is not to be passed to the twins yet (an estimator recovering
    /// from a divergence); the auxiliary model still takes it.
    bool reportable = true;
    /// Set when the best fit the method found stays poor: its NRMSE [-] (the Inspector says
    /// the model family cannot represent the specimen).
    std::optional<double> modelInadequate;
};

class Identifier {
public:
    virtual ~Identifier() = default;
    virtual std::string methodName() const = 0;
    /// The identified parameters' names in their fixed order, for the identifier's lifetime:
    /// estimate(), standardDeviation() and bounds() are in this order (records use it too).
    virtual const ParameterLayout& layout() const = 0;

    /// One committed step of the specimen: measured deformation and force (physical units).
    /// updateRequested: the Inspector asks for an update now (Nelder-Mead runs only then).
    virtual IdentificationStatus observe(double deformation, double force,
                                         bool updateRequested) = 0;

    /// The estimate, in layout() order (valid until the next observe() or setBounds()).
    virtual std::span<const double> estimate() const = 0;
    /// Standard deviations in layout() order (0 where the method has none, e.g. Nelder-Mead).
    virtual std::span<const double> standardDeviation() const = 0;
    /// The model's force predicted for the last observed step before that step's update
    /// (physical units); NaN if the method has no running prediction.
    virtual double predictedForce() const = 0;

    /// Bounds in layout() order; NaN lower and upper where a parameter has none (yet).
    virtual std::span<const ParameterBounds> bounds() const = 0;
    /// Change the bound of parameter `index` between steps; false if the method does not
    /// bound it, lower > upper or index >= layout().size().
    virtual bool setBounds(std::size_t index, const ParameterBounds& b) = 0;
    /// Lock parameter `index` at its current estimate (or unlock it) between steps; false if
    /// the method cannot lock it (the default: no locking).
    virtual bool setLocked(std::size_t /*index*/, bool /*locked*/) { return false; }
    virtual bool locked(std::size_t /*index*/) const { return false; }
    virtual bool canLock() const { return false; }
    /// Compute time of the last update [s] (for Nelder-Mead triggers).
    virtual double lastComputeSeconds() const { return 0.0; }
};

} // namespace hsmu
