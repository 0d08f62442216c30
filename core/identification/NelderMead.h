#pragma once
// NelderMead: bounded Nelder-Mead simplex minimizer (Lagarias et al. 1998, the paper's ref. [17];
// docs/method.md, Nelder-Mead over the history: the slow identification run only at
// triggered steps).
//
// Method: n + 1 vertices; each iteration reflects the worst vertex through the centroid of
// the others and expands, contracts (outside or inside) or shrinks the simplex. Coefficients
// are the dimension-adaptive ones of Gao & Han (2012): reflection 1, expansion 1 + 2/n,
// contraction 0.75 - 1/(2n), shrink 1 - 1/n (the classic 1, 2, 1/2, 1/2 for n = 2); they
// keep the method effective beyond n ~ 5.
// Initial simplex: x0 and x0 + h_i e_i with h_i = initialStep (box width of component i, or
// max(|x0_i|, 1) where the box is unbounded), stepping inwards when x0 + h_i e_i would leave
// the box.
// Bounds: every trial point is *clamped* into the box [lower, upper] component-wise before it
// is evaluated (never reflected: a clamped point is the nearest feasible one, and the
// objective is never called outside the box). Clamping can flatten the simplex against a face;
// the restarts below rebuild it.
// Convergence: when the spread of f over the simplex is <= fTolerance (absolute) +
// fRelativeTolerance |f_best| and every vertex is within xTolerance (relative to the scale
// of each component, as h_i) of the best one, the method restarts from the best vertex with
// a fresh initial simplex, up to maxRestarts times; it stops Converged when a restart does not
// improve f_best by more than the f tolerance. A restart is the standard remedy for a
// collapsed simplex (Nelder-Mead can stall on non-stationary points).
// Non-finite objective values count as +infinity (the simplex moves away from them).
// maxEvaluations is a hard limit: the objective is never called more often.

#include <Eigen/Core>

#include <functional>
#include <string>

namespace hsmu {

struct NelderMeadSettings {
    int maxEvaluations = 1000;
    double fTolerance = 1e-12;         ///< absolute spread of f over the simplex
    double fRelativeTolerance = 1e-10; ///< ... plus this fraction of |f_best|
    double xTolerance = 1e-8;          ///< vertex distance from the best, fraction of the scale
    double initialStep = 0.1;          ///< fraction of the box width (or of max(|x0|, 1))
    int maxRestarts = 3;
};

enum class NelderMeadStop {
    Converged,      ///< tolerances met and a restart brought no improvement
    MaxEvaluations, ///< the evaluation budget is spent; x is the best point found
    InvalidInput    ///< sizes differ, lower > upper, x0 not finite, or maxEvaluations < 1
};

/// Words for a stop reason (for logs). Not named toString (Qt Test ADL).
const char* nelderMeadStopName(NelderMeadStop stop);

struct NelderMeadResult {
    Eigen::VectorXd x;   ///< best point (inside the box)
    double f = 0.0;      ///< objective at x (+inf if no finite value was found)
    int evaluations = 0; ///< objective calls made
    int iterations = 0;  ///< simplex iterations
    int restarts = 0;    ///< restarts made
    NelderMeadStop stop = NelderMeadStop::InvalidInput;
    std::string reason; ///< a sentence for the log
};

class NelderMead {
public:
    using Objective = std::function<double(const Eigen::VectorXd&)>;

    explicit NelderMead(const NelderMeadSettings& settings = {}) : m_settings(settings) {}
    const NelderMeadSettings& settings() const { return m_settings; }
    void setSettings(const NelderMeadSettings& settings) { m_settings = settings; }

    /// Minimize f from x0 (clamped into the box) over [lower, upper] (entries may be +-inf).
    NelderMeadResult minimize(const Objective& f, const Eigen::VectorXd& x0,
                              const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) const;
    /// Unbounded.
    NelderMeadResult minimize(const Objective& f, const Eigen::VectorXd& x0) const;

private:
    NelderMeadSettings m_settings;
};

} // namespace hsmu
