#pragma once
// HysteresisLaw: a uniaxial force-deformation law with trial / commit / revert state.
//
// Units are the caller's: a rotational spring uses rad and kN m, a lateral spring m and kN.
// The contract (same as an OpenSees UniaxialMaterial):
//   setTrialDeformation(u) evaluates the law for total deformation u starting from the
//   *committed* state; it may be called any number of times before commit() and never
//   changes the committed state. commit() accepts the last trial, revert() drops it,
//   revertToStart() returns to the virgin state.
// Thread rules: none; an instance is used by one thread at a time.

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace hsmu {

/// Outcome of a trial evaluation. Anything but Ok leaves the law at its committed state.
enum class LawStatus {
    Ok,
    NoConvergence, ///< the local solver did not converge even after sub-stepping
    InvalidInput   ///< deformation is not finite
};

/// For a replay of a measured history whose sample k was taken at time[k] [s]: the time
/// increment into sample k, time[k] - time[k - 1], and +infinity for k = 0 (a history starts
/// from the virgin state at rest, reached quasi-statically; for a run's record the first
/// sample is one step from rest at u = 0, for an imported test wherever the specimen was when
/// the recording began). NaN if k is beyond time.
double historyTimeIncrement(std::span<const double> time, std::size_t k);

/// Words for a status (for messages; the GUI translates its own). Not named toString: Qt Test
/// would find it by ADL in QCOMPARE and delete[] the literal.
const char* lawStatusName(LawStatus status);

class HysteresisLaw {
public:
    virtual ~HysteresisLaw() = default;

    /// Short law identifier as used in configurations: "boucWen", "bilinear", "elastic".
    virtual std::string lawName() const = 0;

    /// Evaluate at total deformation u from the committed state.
    virtual LawStatus setTrialDeformation(double u) = 0;
    virtual double trialDeformation() const = 0;
    virtual double trialForce() const = 0;
    /// Tangent dF/du at the trial state (force units per deformation unit).
    virtual double trialTangent() const = 0;
    /// The algorithmic (consistent) tangent: the derivative of the trial force with respect to
    /// the trial deformation through the law's integration from the committed state, as
    /// OpenSees' uniaxial material getTangent() defines it (what an OpenFresco element server
    /// reports for action 13). Equal to trialTangent() for laws whose update is exact.
    virtual double algorithmicTangent() const { return trialTangent(); }

    // Rate-dependent laws (docs/hysteresis-laws.md, "Rate-dependent laws"): the force depends
    // on how fast the deformation changes (mrDamper). Such a law takes the velocity of a trial
    // as (u - committed u) / dt, dt being the time from the committed state to the trial. The
    // owner sets dt before driving it: once when its step is constant (a structure's element,
    // the virtual specimen, the auxiliary model: the integration step), per sample when it is
    // not (a replay of a measured history: the samples' times). dt is kept until set again,
    // copied by clone(), untouched by commit(), revert() and revertToStart(); +infinity is a
    // quasi-static step (velocity 0). A rate-dependent law whose dt was never set (or is not
    // > 0) refuses setTrialDeformation() with InvalidInput and says why in failureReason().
    // Rate-independent laws ignore dt (the defaults below).

    /// True for a law whose force depends on the deformation rate.
    virtual bool isRateDependent() const { return false; }
    /// The time from the committed state to the next trials [s]; see above.
    virtual void setTimeIncrement(double /*dt*/) {}
    /// The time increment in use; NaN if never set (and for rate-independent laws).
    virtual double timeIncrement() const;

    /// Why the last setTrialDeformation() failed, when the status alone does not say (a law
    /// computed by another program: "OpenSees twin: no reply within 10 s"); "" otherwise.
    virtual std::string failureReason() const { return {}; }

    virtual double committedDeformation() const = 0;
    virtual double committedForce() const = 0;

    /// Tangent of the virgin law at zero deformation.
    virtual double initialTangent() const = 0;

    virtual void commit() = 0;
    virtual void revert() = 0;
    virtual void revertToStart() = 0;

    /// Deep copy including the current committed and trial state.
    virtual std::unique_ptr<HysteresisLaw> clone() const = 0;

    // Parameters by position (docs/method.md, "Parameters by position"): the layout is
    // parameterNames(), fixed for the law's lifetime. Names are resolved to positions once,
    // at the edges (configuration, console, output), with parameterIndex().

    /// The parameters' names (as in configurations), in their fixed order.
    virtual std::vector<std::string> parameterNames() const = 0;
    /// Position of `name` in parameterNames(); -1 if the law has no such parameter.
    int parameterIndex(const std::string& name) const;
    /// The parameter at `index`; NaN if index is not a position in parameterNames().
    virtual double parameterValue(int index) const = 0;
    /// Set values[k] to the parameter at indices[k], k = 0, 1, ... in order. With
    /// allOrNothing the values are judged together, as one parameter set: an admissible set is
    /// applied even if setting its values one by one would pass through an inadmissible one
    /// (Bouc-Wen's beta and gamma changing sign together); a refused set changes nothing and
    /// returns the position k of the first value that is refused on its own (an unknown index
    /// or an inadmissible value), else 0. Without it each value is judged on the values set
    /// before it and a refused one is skipped. Returns -1 if all were set. The committed state
    /// is kept (e.g. z, e of Bouc-Wen), so the force stays continuous apart from what the new
    /// parameters imply; a pending trial is dropped.
    /// Precondition: indices.size() == values.size().
    virtual int setParameterValues(std::span<const int> indices, std::span<const double> values,
                                   bool allOrNothing) = 0;
    /// One value: setParameterValues({index}, {value}, true) == -1.
    bool setParameterValue(int index, double value);
};

} // namespace hsmu
