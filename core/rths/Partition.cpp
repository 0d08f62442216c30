#include "core/rths/Partition.h"

#include <Eigen/Dense>

#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>

namespace hsmu::rths {

Partition partition(const LinearStructure& r, const Specimen& s)
{
    const auto n = r.m.rows();
    if (s.dof < 0 || s.dof >= n)
        throw std::invalid_argument("partition: the specimen's DOF is outside the structure");
    Partition p{r, r, s};
    p.numerical.m(s.dof, s.dof) -= s.me;
    p.numerical.c(s.dof, s.dof) -= s.ce;
    p.numerical.k(s.dof, s.dof) -= s.ke;
    if (!(p.numerical.m(s.dof, s.dof) > 0.0))
        throw std::invalid_argument("partition: the specimen's mass is not below the DOF's mass");
    return p;
}

namespace {

struct Modes {
    Eigen::VectorXd omega; // [rad/s]
    Eigen::MatrixXd phi;   // columns
};

Modes modes(const Eigen::MatrixXd& m, const Eigen::MatrixXd& k)
{
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(k, m);
    if (es.info() != Eigen::Success)
        throw std::invalid_argument("modal analysis failed: M must be positive definite");
    return {es.eigenvalues().cwiseMax(0.0).cwiseSqrt(), es.eigenvectors()};
}

} // namespace

Eigen::VectorXd naturalFrequencies(const Eigen::MatrixXd& m, const Eigen::MatrixXd& k)
{
    return modes(m, k).omega / (2.0 * M_PI);
}

Eigen::MatrixXd modalDamping(const Eigen::MatrixXd& m, const Eigen::MatrixXd& k, double zeta,
                             double roundTo)
{
    const Modes md = modes(m, k);
    const auto n = m.rows();
    Eigen::VectorXd d(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        double w = md.omega(i);
        if (roundTo > 0.0)
            w = std::round(w / roundTo) * roundTo;
        const double mi = md.phi.col(i).dot(m * md.phi.col(i));
        d(i) = 2.0 * zeta * w * mi;
    }
    const Eigen::MatrixXd phiInv = md.phi.inverse();
    return phiInv.transpose() * d.asDiagonal() * phiInv;
}

LinearStructure benchmarkReference(int benchmarkCase)
{
    static const double mass[] = {1000.0, 1100.0, 1300.0, 1000.0};
    static const double zeta[] = {0.05, 0.04, 0.03, 0.03};
    if (benchmarkCase < 1 || benchmarkCase > 4)
        throw std::invalid_argument("the RTHS benchmark has cases 1 to 4");
    LinearStructure r;
    r.k.resize(3, 3);
    r.k << 2.60549e7, -2.31339e7, 5.93704e6, //
        -2.31339e7, 3.25608e7, -1.44200e7,   //
        5.93704e6, -1.44200e7, 9.26728e6;
    r.m = Eigen::MatrixXd::Identity(3, 3) * mass[benchmarkCase - 1];
    r.c = modalDamping(r.m, r.k, zeta[benchmarkCase - 1], 0.01);
    r.iota = Eigen::VectorXd::Ones(3);
    return r;
}

double criticalDelay(const Partition& p)
{
    const auto& n = p.numerical;
    const int j = p.specimen.dof;
    using C = std::complex<double>;
    const auto loopGain = [&](double w) {
        const Eigen::MatrixXcd dyn = n.k.cast<C>() - w * w * n.m.cast<C>() + C(0.0, w) * n.c.cast<C>();
        const Eigen::VectorXcd col = dyn.partialPivLu().solve(Eigen::VectorXcd::Unit(n.m.rows(), j));
        const C ge = p.specimen.ke - w * w * p.specimen.me + C(0.0, w) * p.specimen.ce;
        return col(j) * ge;
    };
    double best = std::numeric_limits<double>::infinity();
    // Log-spaced scan of 0.01 .. 10,000 rad/s; each crossing of |L| = 1 refined by bisection.
    const int points = 40000;
    const double lo = std::log(1e-2), hi = std::log(1e4);
    double wPrev = std::exp(lo);
    double gPrev = std::abs(loopGain(wPrev)) - 1.0;
    for (int i = 1; i <= points; ++i) {
        const double w = std::exp(lo + (hi - lo) * i / points);
        const double g = std::abs(loopGain(w)) - 1.0;
        if ((g >= 0.0) != (gPrev >= 0.0)) {
            double a = wPrev, b = w, ga = gPrev;
            for (int it = 0; it < 80; ++it) {
                const double mid = 0.5 * (a + b);
                const double gm = std::abs(loopGain(mid)) - 1.0;
                if ((gm >= 0.0) == (ga >= 0.0)) {
                    a = mid;
                    ga = gm;
                } else {
                    b = mid;
                }
            }
            const double wc = 0.5 * (a + b);
            // L e^{-j wc tau} = -1  =>  tau = mod(arg L - pi, 2 pi) / wc
            double phase = std::arg(loopGain(wc)) - M_PI;
            phase = std::fmod(phase, 2.0 * M_PI);
            if (phase < 0.0)
                phase += 2.0 * M_PI;
            best = std::min(best, phase / wc);
        }
        wPrev = w;
        gPrev = g;
    }
    return best;
}

} // namespace hsmu::rths
