#pragma once
// Identifier: parameter identification of one specimen's law from its measured response
// (docs/method.md, The four modules and The paper's UKF). Implementations: UkfIdentifier,
// RobustUkfIdentifier and PinchingUkfIdentifier (every step) and NelderMeadIdentifier (over
// the stored history, when the Inspector asks).
// Values are in the law's own units (normalized for Bouc-Wen with uRef/fRef).

#include "core/identification/ParameterSet.h"

#include <optional>
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
    /// Names of the identified parameters, in a fixed order (records use it).
    virtual std::vector<std::string> parameterNames() const = 0;

    /// One committed step of the specimen: measured deformation and force (physical units).
    /// updateRequested: the Inspector asks for an update now (Nelder-Mead runs only then).
    virtual IdentificationStatus observe(double deformation, double force,
                                         bool updateRequested) = 0;

    virtual ParameterValues estimate() const = 0;
    /// Standard deviations (0 where the method has none, e.g. Nelder-Mead).
    virtual ParameterValues standardDeviation() const = 0;
    /// The model's force predicted for the last observed step before that step's update
    /// (physical units); NaN if the method has no running prediction.
    virtual double predictedForce() const = 0;

    virtual const ParameterBoundsMap& bounds() const = 0;
    /// Change a bound between steps; false if the name is not identified or lower > upper.
    virtual bool setBounds(const std::string& name, const ParameterBounds& b) = 0;
    /// Lock a parameter at its current estimate (or unlock it) between steps; false if the
    /// method cannot lock it (the default: no locking) or the name is not identified.
    virtual bool setLocked(const std::string& /*name*/, bool /*locked*/) { return false; }
    virtual bool locked(const std::string& /*name*/) const { return false; }
    virtual bool canLock() const { return false; }
    /// Compute time of the last update [s] (for Nelder-Mead triggers).
    virtual double lastComputeSeconds() const { return 0.0; }

    // The same by position, for callers that run every step (ModelUpdater): no lookups by
    // name and, once `out` has its size, no allocation. The layout is estimateNames(): the
    // names estimate() returns, in its (sorted) order, fixed for the identifier's lifetime.
    // The defaults go through the maps above; UkfIdentifier overrides them.

    /// The names of estimate(), sorted as ParameterValues sorts them.
    virtual std::vector<std::string> estimateNames() const;
    /// estimate() in estimateNames() order.
    virtual void estimateValues(std::vector<double>& out) const;
    /// standardDeviation() in estimateNames() order (0 where it has no entry).
    virtual void standardDeviationValues(std::vector<double>& out) const;
    /// bounds() in estimateNames() order; NaN lower and upper where a name has no bounds.
    virtual void boundsValues(std::vector<ParameterBounds>& out) const;
};

} // namespace hsmu
