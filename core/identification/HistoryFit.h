#pragma once
// HistoryFit: the paper's Nelder-Mead identification over the stored history (docs/method.md,
// Nelder-Mead over the history and Bilinear law; the bilinear example of the paper's
// Figures 1-2).
//
// Given the measured deformation u_k and force F_k of a specimen (k = 0 .. N-1, physical
// units) and a law with initial parameters, it minimizes over the named parameters, inside
// their bounds, the RMS force error of the law replayed from its virgin state:
//   J(p) = sqrt( 1/W sum_{k = N-W}^{N-1} (F_law(u_0 .. u_k; p) - F_k)^2 )
// W = window (0 = the whole history). The replay always starts at u_0 from the virgin state
// (the law's force depends on the whole path); only the error sum is restricted to the last
// W points. A replay whose law fails (LawStatus not Ok) or whose parameters the law refuses
// scores +infinity, so the simplex moves away from it. NelderMead.h gives the method, the
// clamping into the bounds and the stopping rules.
// Parameters are in the law's own units (normalized for Bouc-Wen with uRef / fRef; physical
// for bilinear). The compute time of the fit (std::chrono::steady_clock) is reported, so that
// a trigger's cost can be compared with the UKF's per-step cost.
// Thread rules: none; fit() is const and may run on a worker thread with its own inputs.

#include "core/identification/NelderMead.h"

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace hsmu {

struct HistoryFitSpec {
    std::string law = "boucWen";           ///< "boucWen" or "bilinear" (LawFactory names)
    std::map<std::string, double> initial; ///< initial values (others: the law's defaults)
    struct Fitted {
        std::string name; ///< a parameter of the law, e.g. "k0"
        double lower = -std::numeric_limits<double>::infinity();
        double upper = std::numeric_limits<double>::infinity();
    };
    std::vector<Fitted> fitted; ///< the parameters to fit, with their bounds
    std::size_t window = 0;     ///< RMS over the last `window` points (0 = all)
    /// The samples' times [s] for a rate-dependent law (HysteresisLaw.h; sample k replayed
    /// with historyTimeIncrement(time, k)); ignored by the others.
    std::vector<double> time;
    NelderMeadSettings optimizer{200, 1e-12, 1e-10, 1e-8, 0.1, 3};
};

struct HistoryFitResult {
    bool ok = false;                          ///< false: nothing was fitted (see reason)
    std::string reason;                       ///< why not, or how the optimizer stopped
    std::map<std::string, double> parameters; ///< all parameters of the law after the fit
    double rmsBefore = 0.0;                   ///< J at the initial parameters [force]
    double rmsAfter = 0.0;                    ///< J at the fitted parameters [force]
    int evaluations = 0;                      ///< replays of the history
    NelderMeadStop stop = NelderMeadStop::InvalidInput;
    double computeSeconds = 0.0; ///< wall time of fit() [s]
};

class HistoryFit {
public:
    explicit HistoryFit(HistoryFitSpec spec) : m_spec(std::move(spec)) {}
    const HistoryFitSpec& spec() const { return m_spec; }

    /// Fit to the history (equal sizes, at least one point, finite values). Not ok, with a
    /// reason, for an unknown law or parameter, inadmissible initial values, bounds with
    /// lower > upper, an initial value outside its bounds or an invalid history.
    HistoryFitResult fit(const std::vector<double>& deformation,
                         const std::vector<double>& force) const;

    /// J(p) for the law built from `parameters` (all of them), as used by fit(); +inf if the
    /// law cannot be built or fails (or is rate-dependent and `time` does not give a time for
    /// every sample).
    static double rmsError(const std::string& law, const std::map<std::string, double>& parameters,
                           const std::vector<double>& deformation, const std::vector<double>& force,
                           std::size_t window, const std::vector<double>& time = {});

private:
    HistoryFitSpec m_spec;
};

} // namespace hsmu
