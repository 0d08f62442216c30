#include "core/identification/NelderMead.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace hsmu {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The evaluation budget and the box, shared by the simplex operations.
class Problem {
public:
    Problem(const NelderMead::Objective& f, const Eigen::VectorXd& lower,
            const Eigen::VectorXd& upper, int budget)
        : m_f(f), m_lower(lower), m_upper(upper), m_budget(budget) {}

    bool exhausted() const { return m_evaluations >= m_budget; }
    int evaluations() const { return m_evaluations; }
    Eigen::VectorXd clamp(const Eigen::VectorXd& x) const {
        return x.cwiseMax(m_lower).cwiseMin(m_upper);
    }
    // Precondition: !exhausted().
    double operator()(const Eigen::VectorXd& x) {
        ++m_evaluations;
        const double v = m_f(x);
        return std::isfinite(v) ? v : kInf;
    }

private:
    const NelderMead::Objective& m_f;
    const Eigen::VectorXd& m_lower;
    const Eigen::VectorXd& m_upper;
    int m_budget;
    int m_evaluations = 0;
};

} // namespace

const char* nelderMeadStopName(NelderMeadStop stop) {
    switch (stop) {
    case NelderMeadStop::Converged:
        return "converged";
    case NelderMeadStop::MaxEvaluations:
        return "maximum number of evaluations";
    case NelderMeadStop::InvalidInput:
        return "invalid input";
    }
    return "unknown";
}

NelderMeadResult NelderMead::minimize(const Objective& f, const Eigen::VectorXd& x0) const {
    const Eigen::Index n = x0.size();
    return minimize(f, x0, Eigen::VectorXd::Constant(n, -kInf), Eigen::VectorXd::Constant(n, kInf));
}

NelderMeadResult NelderMead::minimize(const Objective& f, const Eigen::VectorXd& x0,
                                      const Eigen::VectorXd& lower,
                                      const Eigen::VectorXd& upper) const {
    NelderMeadResult result;
    result.x = x0;
    result.f = kInf;
    const Eigen::Index n = x0.size();
    if (n == 0 || lower.size() != n || upper.size() != n || !x0.allFinite() ||
        (lower.array() > upper.array()).any() || lower.array().isNaN().any() ||
        upper.array().isNaN().any() || m_settings.maxEvaluations < 1 || !f) {
        result.reason = "invalid input: sizes, bounds (lower <= upper), a finite start and at "
                        "least one evaluation are required";
        return result;
    }
    Problem problem(f, lower, upper, m_settings.maxEvaluations);

    // Scale of each component: box width where bounded, else max(|x0|, 1).
    Eigen::VectorXd scale(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double width = upper(i) - lower(i);
        scale(i) = std::isfinite(width) ? width : std::max(std::abs(x0(i)), 1.0);
    }
    const double dn = static_cast<double>(n);
    const double rho = 1.0, chi = 1.0 + 2.0 / dn, psi = 0.75 - 0.5 / dn;
    const double sigma = n > 1 ? 1.0 - 1.0 / dn : 0.5;

    std::vector<Eigen::VectorXd> x(static_cast<std::size_t>(n + 1));
    std::vector<double> fx(static_cast<std::size_t>(n + 1), kInf);
    std::vector<std::size_t> order(static_cast<std::size_t>(n + 1));
    Eigen::VectorXd best = problem.clamp(x0);
    double fBest = kInf;

    // Builds the initial simplex around `best`; false when the budget ran out.
    const auto buildSimplex = [&]() {
        x[0] = best;
        if (!std::isfinite(fBest)) {
            if (problem.exhausted()) {
                return false;
            }
            fBest = problem(best);
        }
        fx[0] = fBest;
        for (Eigen::Index i = 0; i < n; ++i) {
            const auto k = static_cast<std::size_t>(i + 1);
            Eigen::VectorXd v = best;
            double h = m_settings.initialStep * scale(i);
            if (v(i) + h > upper(i)) {
                h = -h;
            }
            v(i) = std::clamp(v(i) + h, lower(i), upper(i));
            if (problem.exhausted()) {
                return false;
            }
            x[k] = v;
            fx[k] = problem(v);
        }
        return true;
    };

    const auto finish = [&](NelderMeadStop stop, std::string reason) {
        for (std::size_t k = 0; k < x.size(); ++k) {
            if (fx[k] < fBest && x[k].size() == n) {
                fBest = fx[k];
                best = x[k];
            }
        }
        result.x = best;
        result.f = fBest;
        result.evaluations = problem.evaluations();
        result.stop = stop;
        result.reason = std::move(reason);
        return result;
    };
    const auto outOfBudget = [&]() {
        return finish(NelderMeadStop::MaxEvaluations,
                      "stopped after the maximum of " + std::to_string(m_settings.maxEvaluations) +
                          " evaluations");
    };

    if (!buildSimplex()) {
        return outOfBudget();
    }
    double fAtRestart = kInf;
    for (;;) {
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return fx[a] < fx[b]; });
        const std::size_t lo = order.front(), hi = order.back(), second = order[order.size() - 2];
        if (fx[lo] < fBest) {
            fBest = fx[lo];
            best = x[lo];
        }

        // Convergence test, then a restart or the stop.
        const double fTol =
            m_settings.fTolerance + m_settings.fRelativeTolerance * std::abs(fx[lo]);
        bool small = fx[hi] - fx[lo] <= fTol;
        for (std::size_t k = 0; small && k < x.size(); ++k) {
            small =
                ((x[k] - x[lo]).cwiseAbs().array() <= m_settings.xTolerance * scale.array()).all();
        }
        if (small) {
            if (result.restarts >= m_settings.maxRestarts || fAtRestart - fBest <= fTol) {
                return finish(NelderMeadStop::Converged,
                              "converged: simplex spread within the tolerances after " +
                                  std::to_string(result.restarts) + " restart(s)");
            }
            fAtRestart = fBest;
            ++result.restarts;
            if (!buildSimplex()) {
                return outOfBudget();
            }
            continue;
        }

        ++result.iterations;
        Eigen::VectorXd centroid = Eigen::VectorXd::Zero(n);
        for (const std::size_t k : order) {
            if (k != hi) {
                centroid += x[k];
            }
        }
        centroid /= dn;
        const auto trial = [&](double t) {
            return problem.clamp(centroid + t * (x[hi] - centroid));
        };

        if (problem.exhausted()) {
            return outOfBudget();
        }
        const Eigen::VectorXd xr = trial(-rho);
        const double fr = problem(xr);
        if (fr < fx[lo]) {
            if (problem.exhausted()) {
                x[hi] = xr;
                fx[hi] = fr;
                return outOfBudget();
            }
            const Eigen::VectorXd xe = trial(-rho * chi);
            const double fe = problem(xe);
            x[hi] = fe < fr ? xe : xr;
            fx[hi] = std::min(fe, fr);
            continue;
        }
        if (fr < fx[second]) {
            x[hi] = xr;
            fx[hi] = fr;
            continue;
        }
        if (problem.exhausted()) {
            return outOfBudget();
        }
        const bool outside = fr < fx[hi];
        const Eigen::VectorXd xc = outside ? trial(-rho * psi) : trial(psi);
        const double fc = problem(xc);
        if (outside ? fc <= fr : fc < fx[hi]) {
            x[hi] = xc;
            fx[hi] = fc;
            continue;
        }
        // Shrink towards the best vertex.
        for (const std::size_t k : order) {
            if (k == lo) {
                continue;
            }
            if (problem.exhausted()) {
                return outOfBudget();
            }
            x[k] = problem.clamp(x[lo] + sigma * (x[k] - x[lo]));
            fx[k] = problem(x[k]);
        }
    }
}

} // namespace hsmu
