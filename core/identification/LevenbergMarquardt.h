#pragma once
// LevenbergMarquardt: bounded nonlinear least squares, min_x 1/2 ||r(x)||^2 over a box
// lower <= x <= upper (docs/method.md, "Offline calibration").
//
// Each iteration solves the damped normal equations on the free variables F (those not held
// on a bound by a gradient pointing out of the box):
//   (J_F^T J_F + lambda diag(J_F^T J_F)) delta_F = -J_F^T r              (Marquardt scaling)
// then projects x + delta onto the box and through the caller's `project` (e.g. the law's
// admissibility: beta + gamma > 0 for Bouc-Wen). The step is accepted when the cost falls
// (lambda /= 3) and rejected otherwise (lambda *= 4, the Jacobian kept). J is the forward-
// difference Jacobian, step h_i = relativeStep max(|x_i|, typical_i). A residual function
// that returns false (the model failed, e.g. a law that does not converge) is an infinite
// cost: the step is rejected.
// Stops: cost reduction below costTolerance (relative) on an accepted step twice in a row,
// a step below stepTolerance (relative to typical), lambda above 1e12, maxIterations, or the
// caller's cancel flag (checked before each iteration).
// Thread rules: none; minimize() is const.

#include <Eigen/Core>

#include <atomic>
#include <functional>
#include <string>

namespace hsmu {

struct LevenbergMarquardtSettings {
    int maxIterations = 60;
    double costTolerance = 1e-8; ///< relative cost decrease that counts as converged
    double stepTolerance = 1e-9; ///< relative step that counts as converged
    double relativeStep = 1e-6;  ///< forward-difference step, fraction of max(|x|, typical)
    double initialLambda = 1e-3;
    /// Checked before each iteration: set (by another thread) stops the minimization with
    /// `cancelled` (the best point so far is returned). May be null.
    const std::atomic<bool>* cancel = nullptr;
};

struct LevenbergMarquardtResult {
    Eigen::VectorXd x;           ///< the best point found
    double cost = 0.0;           ///< 1/2 ||r(x)||^2 (+inf if no finite residual was found)
    Eigen::MatrixXd jacobian;    ///< J at x (empty if never evaluated there)
    int iterations = 0;          ///< accepted and rejected steps
    int residualEvaluations = 0; ///< calls of the residual function (Jacobians included)
    bool converged = false;      ///< a tolerance was met (not the iteration budget)
    bool cancelled = false;      ///< stopped by settings.cancel
};

class LevenbergMarquardt {
public:
    /// r(x) into `residual` (sized by the callee); false if x cannot be evaluated.
    using Residual = std::function<bool(const Eigen::VectorXd& x, Eigen::VectorXd& residual)>;
    /// Maps a point of the box onto the admissible set (in place); may be empty.
    using Projection = std::function<void(Eigen::VectorXd& x)>;

    explicit LevenbergMarquardt(const LevenbergMarquardtSettings& s = {}) : m_settings(s) {}

    /// typical: the scale of each variable (> 0), for the difference steps and tolerances.
    LevenbergMarquardtResult minimize(const Residual& residual, const Eigen::VectorXd& x0,
                                      const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                                      const Eigen::VectorXd& typical,
                                      const Projection& project = {}) const;

    /// The forward-difference Jacobian of r at x (r0 = r(x) given); false if a column fails.
    /// Steps go inward at an upper bound so that x + h stays in the box.
    static bool jacobian(const Residual& residual, const Eigen::VectorXd& x,
                         const Eigen::VectorXd& r0, const Eigen::VectorXd& upper,
                         const Eigen::VectorXd& typical, double relativeStep, Eigen::MatrixXd& J,
                         int& evaluations);

private:
    LevenbergMarquardtSettings m_settings;
};

} // namespace hsmu
