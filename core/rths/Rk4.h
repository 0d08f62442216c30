#pragma once
// One classical Runge-Kutta step of x'' = acc(x, v, s) over h (docs/rths.md, "The loop"), s the
// stage's time as a fraction of h (0, 1/2 or 1); a0 = acc(x, v, 0), already known. The RTHS
// loop's numerical substructure and the reference structures step with it.

#include <Eigen/Core>

namespace hsmu::rths {

template <class Acceleration>
void rk4Step(Eigen::VectorXd& x, Eigen::VectorXd& v, double h, const Eigen::VectorXd& a0,
             const Acceleration& acc)
{
    const Eigen::VectorXd k1x = v, k1v = a0;
    const Eigen::VectorXd k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, k2x, 0.5);
    const Eigen::VectorXd k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, k3x, 0.5);
    const Eigen::VectorXd k4x = v + h * k3v, k4v = acc(x + h * k3x, k4x, 1.0);
    x += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
}

} // namespace hsmu::rths
