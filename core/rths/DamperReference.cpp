#include "core/rths/DamperReference.h"

#include "core/rths/Rk4.h"

#include <Eigen/Dense>

#include <stdexcept>

namespace hsmu::rths {

Eigen::MatrixXd referenceResponse(const LinearStructure& r, const GroundMotion& ag, double h,
                                  long n, const ReferenceDampers& dampers)
{
    const Eigen::MatrixXd mInv = r.m.inverse();
    const Eigen::VectorXd load = r.m * r.iota;
    const auto dofs = r.m.rows();
    // The dampers' storey forces, stepped once per tick at the tick's start and held over it
    // (the loop's operator splitting, docs/rths.md "A damper and its twin").
    std::vector<MrDamper> laws;
    for (const auto& d : dampers.storeys) {
        if (d.first < 0 || d.first >= int(dofs))
            throw std::invalid_argument("RTHS: a reference damper's DOF must be one of the structure's");
        laws.emplace_back(d.second);
        laws.back().setTimeIncrement(h);
    }
    Eigen::VectorXd storeyForces = Eigen::VectorXd::Zero(dofs);
    const auto acc = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& v, double a) {
        return Eigen::VectorXd(mInv * (-load * a - r.c * v - r.k * x - storeyForces));
    };
    Eigen::MatrixXd out(n, dofs);
    Eigen::VectorXd x = Eigen::VectorXd::Zero(dofs), v = x;
    for (long k = 0; k < n; ++k) {
        out.row(k) = x.transpose();
        storeyForces.setZero();
        for (std::size_t i = 0; i < laws.size(); ++i) {
            const int d = dampers.storeys[i].first;
            const double drift = x(d) - (d > 0 ? x(d - 1) : 0.0);
            if (laws[i].setTrialDeformation(drift) == LawStatus::Ok)
                laws[i].commit();
            else
                laws[i].revert();
            const double f = laws[i].committedForce();
            storeyForces(d) += f;
            if (d > 0)
                storeyForces(d - 1) -= f;
        }
        const double t = double(k) * h;
        const double a0 = ag.at(t), am = ag.at(t + 0.5 * h), a1 = ag.at(t + h);
        rk4Step(x, v, h, acc(x, v, a0),
                [&](const Eigen::VectorXd& xs, const Eigen::VectorXd& vs, double s) {
                    return acc(xs, vs, s < 1.0 ? am : a1);
                });
    }
    return out;
}

ReferenceDampers referenceDampers(const Partition& p, const DamperSettings& d)
{
    ReferenceDampers r;
    if (!d.enabled)
        return r;
    r.storeys.emplace_back(p.specimen.dof, d.specimen); // the physical damper, at the specimen
    r.storeys.emplace_back(d.twinDof, d.specimen);      // the device the twin models, its true law
    return r;
}

} // namespace hsmu::rths
