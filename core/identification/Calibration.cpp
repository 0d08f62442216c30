#include "core/identification/Calibration.h"

#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"
#include "core/identification/HistoryScales.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <numeric>
#include <span>

namespace hsmu {

namespace {

/// Replays a law along chosen samples and returns the scaled force residuals.
class Replay {
public:
    /// Residuals of the kept samples k >= firstScored (the others are replayed only).
    /// time: the samples' times for a rate-dependent law (every sample kept), else empty.
    Replay(HysteresisLaw& law, std::vector<int> indices, const std::vector<double>& u,
           const std::vector<double>& f, std::vector<std::size_t> keep, double scale,
           std::size_t firstScored = 0, std::span<const double> time = {})
        : m_law(law), m_indices(std::move(indices)), m_u(u), m_f(f), m_keep(std::move(keep)),
          m_scale(scale), m_firstScored(firstScored), m_time(time) {
        for (std::size_t k : m_keep)
            m_scored += k >= m_firstScored;
    }

    bool operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
        return run(x, std::numeric_limits<double>::infinity(), r);
    }

    /// 1/2 ||r(x)||^2 as operator() gives it (the same residuals, the same sum), or false when
    /// the replay fails or when the running sum of the squared residuals passes 2 `above`
    /// (with a margin far above the two sums' roundings): the replay stops there, since the
    /// cost only grows with more samples.
    bool costUpTo(const Eigen::VectorXd& x, double above, Eigen::VectorXd& r, double& cost) const {
        if (!run(x, 2.0 * above * (1.0 + 1e-9), r))
            return false;
        cost = 0.5 * r.squaredNorm();
        return true;
    }

private:
    /// The replay, stopped (false) once the running sum of squared residuals passes limit.
    bool run(const Eigen::VectorXd& x, double limit, Eigen::VectorXd& r) const {
        if (m_law.setParameterValues(m_indices, {x.data(), std::size_t(x.size())}, true) != -1)
            return false;
        m_law.revertToStart();
        r.resize(Eigen::Index(m_scored));
        double running = 0.0;
        Eigen::Index j = 0;
        for (const std::size_t k : m_keep) {
            if (!m_time.empty())
                m_law.setTimeIncrement(historyTimeIncrement(m_time, k));
            if (m_law.setTrialDeformation(m_u[k]) != LawStatus::Ok)
                return false;
            m_law.commit();
            if (k >= m_firstScored) {
                const double e = (m_law.committedForce() - m_f[k]) / m_scale;
                r[j++] = e;
                running += e * e;
                if (running > limit) // (a NaN never passes: allFinite() below)
                    return false;
            }
        }
        return r.allFinite();
    }

    HysteresisLaw& m_law;
    std::vector<int> m_indices;
    const std::vector<double>& m_u;
    const std::vector<double>& m_f;
    std::vector<std::size_t> m_keep;
    double m_scale;
    std::size_t m_firstScored = 0, m_scored = 0;
    std::span<const double> m_time;
};

struct Candidate {
    Eigen::VectorXd x;
    double cost;
};

} // namespace

void projectBetaGamma(Eigen::VectorXd& x, int iBeta, int iGamma, double fixedBeta,
                      double fixedGamma) {
    if (iBeta < 0 && iGamma < 0)
        return;
    const double beta = iBeta >= 0 ? x[iBeta] : fixedBeta;
    const double gamma = iGamma >= 0 ? x[iGamma] : fixedGamma;
    if (iBeta >= 0 && iGamma >= 0) {
        BoucWen::projectBetaGamma(x[iBeta], x[iGamma]);
        return;
    }
    const double deficit = BoucWen::kBetaGammaMargin - (beta + gamma);
    if (!(deficit > 0))
        return;
    if (iBeta >= 0) {
        x[iBeta] += deficit;
    } else {
        x[iGamma] += deficit;
    }
}

std::vector<std::size_t> reducedHistory(const std::vector<double>& u, std::size_t target) {
    std::vector<std::size_t> keep;
    if (u.size() <= target || target < 2) {
        keep.resize(u.size());
        std::iota(keep.begin(), keep.end(), std::size_t(0));
        return keep;
    }
    const auto [lo, hi] = std::minmax_element(u.begin(), u.end());
    const std::vector<std::size_t> tps = turningPoints(u, 0.01 * (*hi - *lo));
    double path = 0.0;
    std::size_t prev = 0;
    for (std::size_t tp : tps) {
        path += std::abs(u[tp] - u[prev]);
        prev = tp;
    }
    path += std::abs(u.back() - u[prev]);
    const double spacing = path / double(target);
    std::size_t next = 0; // next turning point to keep
    keep.push_back(0);
    double last = u[0];
    for (std::size_t k = 1; k + 1 < u.size(); ++k) {
        const bool turning = next < tps.size() && tps[next] == k;
        if (turning)
            ++next;
        if (turning || std::abs(u[k] - last) >= spacing) {
            keep.push_back(k);
            last = u[k];
        }
    }
    keep.push_back(u.size() - 1);
    return keep;
}

CalibrationResult calibrate(const std::vector<double>& u, const std::vector<double>& f,
                            const CalibrationSpec& spec) {
    const auto start = std::chrono::steady_clock::now();
    CalibrationResult out;
    const auto done = [&](std::string reason) {
        out.reason = std::move(reason);
        out.computeSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return out;
    };
    if (u.size() < 3 || u.size() != f.size())
        return done("the history needs equally many deformations and forces (at least 3)");
    if (!std::all_of(u.begin(), u.end(), [](double v) { return std::isfinite(v); }) ||
        !std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); }))
        return done("the history contains a non-finite value");
    if (spec.fitted.empty() || spec.starts.empty())
        return done("no parameter to fit or no start");
    std::unique_ptr<HysteresisLaw> law;
    try {
        law = makeLaw(spec.law, spec.fixed);
    } catch (const std::exception& e) {
        return done(e.what());
    }
    const bool rate = law->isRateDependent();
    if (rate && spec.time.size() != u.size())
        return done(spec.law + " is rate-dependent: the calibration needs the samples' times");
    const std::span<const double> time =
        rate ? std::span<const double>(spec.time) : std::span<const double>();
    const auto p = Eigen::Index(spec.fitted.size());
    std::vector<int> indices;
    Eigen::VectorXd lower(p), upper(p), typical(p), searchLower(p), searchUpper(p);
    int iBeta = -1, iGamma = -1;
    for (Eigen::Index i = 0; i < p; ++i) {
        const CalibrationSpec::Parameter& q = spec.fitted[std::size_t(i)];
        const int index = law->parameterIndex(q.name);
        if (index < 0)
            return done(spec.law + ": unknown parameter '" + q.name + "'");
        if (!(q.lower <= q.upper) || !std::isfinite(q.lower) || !std::isfinite(q.upper) ||
            !(q.typical > 0))
            return done(q.name + ": the box needs finite lower <= upper and a typical > 0");
        indices.push_back(index);
        lower[i] = q.lower;
        upper[i] = q.upper;
        typical[i] = q.typical;
        searchLower[i] = std::isnan(q.searchLower) ? q.lower : std::max(q.lower, q.searchLower);
        searchUpper[i] = std::isnan(q.searchUpper) ? q.upper : std::min(q.upper, q.searchUpper);
        if (!(searchLower[i] <= searchUpper[i]))
            return done(q.name + ": the search range lies outside the box");
        out.names.push_back(q.name);
        if (q.name == "beta")
            iBeta = int(i);
        if (q.name == "gamma")
            iGamma = int(i);
    }
    const int lawBeta = law->parameterIndex("beta"), lawGamma = law->parameterIndex("gamma");
    const double fixedBeta = lawBeta >= 0 ? law->parameterValue(lawBeta) : 1.0;
    const double fixedGamma = lawGamma >= 0 ? law->parameterValue(lawGamma) : 0.0;
    const LevenbergMarquardt::Projection project = [&](Eigen::VectorXd& x) {
        projectBetaGamma(x, iBeta, iGamma, fixedBeta, fixedGamma);
    };
    const std::size_t first =
        spec.window > 0 && spec.window < u.size() ? u.size() - spec.window : 0;
    const std::size_t scored = u.size() - first;
    double sumF2 = 0.0;
    for (std::size_t k = first; k < f.size(); ++k)
        sumF2 += f[k] * f[k];
    const double rmsF = std::sqrt(sumF2 / double(scored));
    if (!(rmsF > 0))
        return done("the measured force is zero throughout");

    // 1. Global phase on the reduced history.
    std::vector<std::size_t> reduced = reducedHistory(u, rate ? u.size() : spec.reducedSamples);
    if (first > 0) {
        // with a window every scored sample is kept (the reduced history only thins the
        // replayed part before it)
        reduced.erase(std::remove_if(reduced.begin(), reduced.end(),
                                     [&](std::size_t k) { return k >= first; }),
                      reduced.end());
        for (std::size_t k = first; k < u.size(); ++k)
            reduced.push_back(k);
    }
    const Replay coarse(*law, indices, u, f, reduced, rmsF, first, time);
    std::vector<Eigen::VectorXd> starts;
    for (const std::vector<double>& s : spec.starts) {
        if (s.size() != spec.fitted.size())
            return done("a start has the wrong number of values");
        starts.push_back(Eigen::Map<const Eigen::VectorXd>(s.data(), p));
    }
    const auto cancelled = [&] {
        return spec.cancel && spec.cancel->load(std::memory_order_relaxed);
    };
    if (!spec.screened.empty()) {
        // 0. Screening: one replay per point on a shorter reduced history, the best kept.
        const Replay screen(*law, indices, u, f,
                            reducedHistory(u, rate ? u.size() : spec.screenSamples), rmsF, 0,
                            time);
        std::vector<Candidate> screenedBest;
        const std::size_t keep = std::size_t(std::max(spec.screenKept, 0));
        // the keep best costs so far (a max-heap): a point whose replay passes the worst of
        // them cannot be kept, and its replay stops there (the same points are kept)
        std::vector<double> bestCosts;
        Eigen::VectorXd r;
        for (const std::vector<double>& s : spec.screened) {
            if (s.size() != spec.fitted.size())
                return done("a screened point has the wrong number of values");
            if (cancelled()) {
                out.cancelled = true;
                return done("cancelled");
            }
            Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(s.data(), p)
                                    .cwiseMax(searchLower)
                                    .cwiseMin(searchUpper);
            project(x);
            ++out.residualEvaluations;
            const double above = bestCosts.size() < keep ? std::numeric_limits<double>::infinity()
                                                         : bestCosts.front();
            double cost = 0.0;
            if (keep == 0 || !screen.costUpTo(x, above, r, cost))
                continue;
            screenedBest.push_back({x, cost});
            bestCosts.push_back(cost);
            std::push_heap(bestCosts.begin(), bestCosts.end());
            if (bestCosts.size() > keep) {
                std::pop_heap(bestCosts.begin(), bestCosts.end());
                bestCosts.pop_back();
            }
        }
        const std::size_t kept =
            std::min(screenedBest.size(), std::size_t(std::max(spec.screenKept, 0)));
        std::partial_sort(screenedBest.begin(), screenedBest.begin() + std::ptrdiff_t(kept),
                          screenedBest.end(),
                          [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });
        for (std::size_t k = 0; k < kept; ++k)
            starts.push_back(screenedBest[k].x);
    }
    LevenbergMarquardtSettings globalSettings = spec.global, localSettings = spec.local;
    globalSettings.cancel = localSettings.cancel = spec.cancel;
    const int minimizations =
        int(starts.size()) + int(std::min(starts.size(), std::size_t(std::max(spec.polished, 1))));
    int minimized = 0;
    const auto tell = [&] {
        if (spec.progress)
            spec.progress(++minimized, minimizations);
    };
    std::vector<Candidate> candidates;
    for (const Eigen::VectorXd& x0 : starts) {
        if (cancelled()) {
            out.cancelled = true;
            return done("cancelled");
        }
        const LevenbergMarquardtResult r =
            LevenbergMarquardt(globalSettings).minimize(coarse, x0, searchLower, searchUpper, typical, project);
        ++out.startsTried;
        out.residualEvaluations += r.residualEvaluations;
        if (std::isfinite(r.cost))
            candidates.push_back({r.x, r.cost});
        tell();
    }
    if (candidates.empty())
        return done("the law could not replay the history from any start");
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& a, const Candidate& b) { return a.cost < b.cost; });

    // 2. Local phase on the whole history.
    std::vector<std::size_t> all;
    if (!rate && spec.polishSamples > 0 && first == 0 && u.size() > spec.polishSamples) {
        all = reducedHistory(u, spec.polishSamples); // a budget (online anchors)
    } else {
        all.resize(u.size());
        std::iota(all.begin(), all.end(), std::size_t(0));
    }
    const std::size_t polishScored = first == 0 ? all.size() : scored;
    const Replay fine(*law, indices, u, f, all, rmsF, first, time);
    LevenbergMarquardtResult best;
    best.cost = std::numeric_limits<double>::infinity();
    const std::size_t polish = std::min(candidates.size(), std::size_t(std::max(spec.polished, 1)));
    for (std::size_t c = 0; c < polish; ++c) {
        if (cancelled()) {
            out.cancelled = true;
            return done("cancelled");
        }
        LevenbergMarquardtResult r = LevenbergMarquardt(localSettings)
                                         .minimize(fine, candidates[c].x, lower, upper, typical,
                                                   project);
        out.residualEvaluations += r.residualEvaluations;
        if (r.cost < best.cost)
            best = std::move(r);
        tell();
    }
    if (cancelled()) {
        out.cancelled = true;
        return done("cancelled");
    }
    if (!std::isfinite(best.cost))
        return done("the law could not replay the whole history from the best starts");

    // 3. The result and its statistics.
    Eigen::VectorXd r;
    fine(best.x, r); // leaves the law at the optimum's parameters
    const std::vector<std::string> lawNames = law->parameterNames();
    for (std::size_t i = 0; i < lawNames.size(); ++i)
        out.parameters[lawNames[i]] = law->parameterValue(static_cast<int>(i));
    out.estimate = best.x;
    out.nrmse = std::sqrt(2.0 * best.cost / double(polishScored));
    out.rmsError = out.nrmse * rmsF;
    out.onBound.resize(std::size_t(p));
    std::vector<Eigen::Index> freeIdx;
    for (Eigen::Index i = 0; i < p; ++i) {
        const double tol = 1e-9 * (upper[i] - lower[i]);
        out.onBound[std::size_t(i)] = best.x[i] <= lower[i] + tol || best.x[i] >= upper[i] - tol;
        if (!out.onBound[std::size_t(i)])
            freeIdx.push_back(i);
    }
    out.standardDeviation = Eigen::VectorXd::Constant(p, std::nan(""));
    out.correlation = Eigen::MatrixXd::Constant(p, p, std::nan(""));
    const auto m = Eigen::Index(freeIdx.size());
    const double dof = double(polishScored) - double(m);
    if (m > 0 && dof > 0 && best.jacobian.cols() == p) {
        Eigen::MatrixXd JF(best.jacobian.rows(), m);
        for (Eigen::Index k = 0; k < m; ++k)
            JF.col(k) = best.jacobian.col(freeIdx[std::size_t(k)]) * rmsF; // force units
        const Eigen::MatrixXd A = JF.transpose() * JF;
        const double s2 = 2.0 * best.cost * rmsF * rmsF / dof;
        Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
        if (lu.isInvertible()) {
            const Eigen::MatrixXd cov = s2 * lu.inverse();
            for (Eigen::Index a = 0; a < m; ++a) {
                const Eigen::Index ia = freeIdx[std::size_t(a)];
                out.standardDeviation[ia] = std::sqrt(std::max(cov(a, a), 0.0));
                for (Eigen::Index b = 0; b < m; ++b) {
                    const Eigen::Index ib = freeIdx[std::size_t(b)];
                    out.correlation(ia, ib) = cov(a, b) / std::sqrt(cov(a, a) * cov(b, b));
                }
            }
        }
    }
    out.ok = true;
    return done(best.converged ? "converged" : "iteration budget spent");
}

} // namespace hsmu
