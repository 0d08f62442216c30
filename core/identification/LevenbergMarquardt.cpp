#include "core/identification/LevenbergMarquardt.h"

#include <Eigen/Cholesky>

#include <cmath>
#include <limits>
#include <vector>

namespace hsmu {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

double costOf(const Eigen::VectorXd& r) {
    const double c = 0.5 * r.squaredNorm();
    return std::isfinite(c) ? c : kInf;
}

} // namespace

bool LevenbergMarquardt::jacobian(const Residual& residual, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& r0, const Eigen::VectorXd& upper,
                                  const Eigen::VectorXd& typical, double relativeStep,
                                  Eigen::MatrixXd& J, int& evaluations) {
    const Eigen::Index n = x.size();
    J.resize(r0.size(), n);
    Eigen::VectorXd xh = x, rh;
    for (Eigen::Index i = 0; i < n; ++i) {
        double h = relativeStep * std::max(std::abs(x[i]), typical[i]);
        if (x[i] + h > upper[i])
            h = -h; // step inward
        xh[i] = x[i] + h;
        h = xh[i] - x[i]; // the step actually represented
        ++evaluations;
        if (!residual(xh, rh) || rh.size() != r0.size() || !rh.allFinite())
            return false;
        J.col(i) = (rh - r0) / h;
        xh[i] = x[i];
    }
    return true;
}

LevenbergMarquardtResult LevenbergMarquardt::minimize(const Residual& residual,
                                                      const Eigen::VectorXd& x0,
                                                      const Eigen::VectorXd& lower,
                                                      const Eigen::VectorXd& upper,
                                                      const Eigen::VectorXd& typical,
                                                      const Projection& project) const {
    const LevenbergMarquardtSettings& s = m_settings;
    const Eigen::Index n = x0.size();
    LevenbergMarquardtResult out;
    const auto feasible = [&](Eigen::VectorXd x) {
        x = x.cwiseMax(lower).cwiseMin(upper);
        if (project)
            project(x);
        return x;
    };
    out.x = feasible(x0);
    Eigen::VectorXd r;
    ++out.residualEvaluations;
    out.cost = residual(out.x, r) ? costOf(r) : kInf;
    if (!std::isfinite(out.cost))
        return out;

    double lambda = s.initialLambda;
    bool needJacobian = true;
    int smallDecreases = 0;
    Eigen::VectorXd g;
    std::vector<Eigen::Index> freeIdx;
    for (out.iterations = 0; out.iterations < s.maxIterations; ++out.iterations) {
        if (s.cancel && s.cancel->load(std::memory_order_relaxed)) {
            out.cancelled = true;
            return out; // no final Jacobian: nobody waits for this result
        }
        if (needJacobian) {
            if (!jacobian(residual, out.x, r, upper, typical, s.relativeStep, out.jacobian,
                          out.residualEvaluations))
                break;
            g = out.jacobian.transpose() * r;
            needJacobian = false;
        }
        freeIdx.clear();
        for (Eigen::Index i = 0; i < n; ++i) {
            const bool heldLow = out.x[i] <= lower[i] && g[i] > 0.0;
            const bool heldHigh = out.x[i] >= upper[i] && g[i] < 0.0;
            if (!heldLow && !heldHigh)
                freeIdx.push_back(i);
        }
        if (freeIdx.empty()) {
            out.converged = true; // a corner of the box is a stationary point
            break;
        }
        const auto m = Eigen::Index(freeIdx.size());
        Eigen::MatrixXd JF(out.jacobian.rows(), m);
        Eigen::VectorXd gF(m);
        for (Eigen::Index k = 0; k < m; ++k) {
            JF.col(k) = out.jacobian.col(freeIdx[std::size_t(k)]);
            gF[k] = g[freeIdx[std::size_t(k)]];
        }
        Eigen::MatrixXd A = JF.transpose() * JF;
        const Eigen::VectorXd d = A.diagonal().cwiseMax(1e-300);
        A.diagonal() += lambda * d;
        const Eigen::VectorXd deltaF = A.ldlt().solve(-gF);
        Eigen::VectorXd trial = out.x;
        for (Eigen::Index k = 0; k < m; ++k)
            trial[freeIdx[std::size_t(k)]] += deltaF[k];
        trial = feasible(trial);
        const double step = ((trial - out.x).array() / typical.array()).abs().maxCoeff();
        Eigen::VectorXd rt;
        ++out.residualEvaluations;
        const double cost = residual(trial, rt) ? costOf(rt) : kInf;
        if (cost < out.cost) {
            const double decrease = (out.cost - cost) / out.cost;
            out.x = trial;
            out.cost = cost;
            r = rt;
            needJacobian = true;
            lambda = std::max(lambda / 3.0, 1e-12);
            smallDecreases = decrease < s.costTolerance ? smallDecreases + 1 : 0;
            if (smallDecreases >= 2 || step < s.stepTolerance) {
                out.converged = true;
                break;
            }
        } else {
            lambda *= 4.0;
            if (lambda > 1e12 || step < s.stepTolerance) {
                out.converged = true;
                break;
            }
        }
    }
    if (needJacobian && std::isfinite(out.cost)) // the Jacobian at the returned point
        jacobian(residual, out.x, r, upper, typical, s.relativeStep, out.jacobian,
                 out.residualEvaluations);
    return out;
}

} // namespace hsmu
