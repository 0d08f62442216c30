#include "core/experimental/SpecimenBehindSetup.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsmu {

SpecimenBehindSetup::SpecimenBehindSetup(std::unique_ptr<ExperimentalSetup> setup,
                                         std::unique_ptr<CantileverColumn> specimen,
                                         std::vector<ActuatorMode> modes)
    : m_setup(std::move(setup)), m_specimen(std::move(specimen)), m_modes(std::move(modes)) {
    if (!m_setup || !m_specimen)
        throw std::invalid_argument("specimen behind setup: needs a setup and a specimen");
    if (m_setup->basicSize() != 3)
        throw std::invalid_argument(m_setup->typeName() + " serves " +
                                    std::to_string(m_setup->basicSize()) +
                                    " basic DOFs, the specimen has 3 (axial, shear, rotation)");
    if (int(m_modes.size()) != m_setup->actuatorCount())
        throw std::invalid_argument(m_setup->typeName() + " has " +
                                    std::to_string(m_setup->actuatorCount()) + " actuators, " +
                                    std::to_string(m_modes.size()) + " channels");
    m_s = m_f = m_cs = m_cf = Eigen::VectorXd::Zero(actuatorCount());
}

std::string SpecimenBehindSetup::description() const {
    return m_specimen->description() + " behind " + m_setup->typeName();
}

std::string SpecimenBehindSetup::solve(const Eigen::VectorXd& a) {
    const int m = actuatorCount(), n = 3 + m;
    Eigen::Vector3d d = m_cd;
    Eigen::VectorXd f = m_cf, s, r(n), step;
    Eigen::MatrixXd j, jp, jm, t(n, n);
    std::string why = m_setup->typeName() + ": no equilibrium of the specimen with the actuators";
    double previous = INFINITY; // the last iterate's largest residual
    for (int it = 0; it < 50; ++it) {
        SetupResult sr = m_setup->strokes(d, s);
        if (sr.ok)
            sr = m_setup->jacobian(d, j);
        if (!sr.ok) {
            why = sr.reason;
            break;
        }
        if (std::string e = m_specimen->setTrial(d); !e.empty()) {
            why = m_setup->typeName() + ": " + e;
            break;
        }
        const Eigen::Vector3d& q = m_specimen->trialForces();
        const Eigen::Vector3d jtf = j.transpose() * f;
        bool done = true;
        t.setZero();
        for (int i = 0; i < m; ++i) {
            if (m_modes[i] == ActuatorMode::Displacement) {
                r[i] = s[i] - a[i];
                done = done && std::abs(r[i]) <= 1e-15 + 1e-12 * std::abs(a[i]);
                t.block(i, 0, 1, 3) = j.row(i);
            } else {
                r[i] = f[i] - a[i];
                done = done && std::abs(r[i]) <= 1e-12 * std::max(1.0, std::abs(a[i]));
                t(i, 3 + i) = 1.0;
            }
        }
        // Each equilibrium row to 1e-12 of its own force; when the residual stops falling,
        // to 1e-12 of the largest basic or actuator force: a small shear beside a large axial
        // force is the difference of the column's larger internal terms (eq. W1, W2), whose
        // round-off Newton cannot beat.
        const double scale = std::max({1.0, q.cwiseAbs().maxCoeff(), f.cwiseAbs().maxCoeff()});
        bool floor = done;
        for (int k = 0; k < 3; ++k) {
            r[m + k] = q[k] - jtf[k];
            done = done && std::abs(r[m + k]) <= 1e-12 * std::max(1.0, std::abs(q[k]));
            floor = floor && std::abs(r[m + k]) <= 1e-12 * scale;
        }
        const double norm = r.cwiseAbs().maxCoeff();
        if (done || (floor && norm >= previous)) {
            m_d = d;
            m_s = s;
            m_f = f;
            return {};
        }
        t.block(m, 0, 3, 3) = m_specimen->trialTangent();
        for (int k = 0; k < 3; ++k) { // G = d(J^T f)/dd (eq. W4)
            const double h = 1e-7;
            Eigen::Vector3d dp = d, dm = d;
            dp[k] += h;
            dm[k] -= h;
            if (!m_setup->jacobian(dp, jp).ok || !m_setup->jacobian(dm, jm).ok)
                continue;
            t.block(m, k, 3, 1) -= (jp - jm).transpose() * f / (2.0 * h);
        }
        t.block(m, 3, 3, m) = -j.transpose();
        previous = norm;
        step = t.partialPivLu().solve(r);
        if (!step.allFinite())
            break;
        d -= step.head<3>();
        f -= step.tail(m);
    }
    m_specimen->revert();
    return why;
}

double SpecimenBehindSetup::channelStiffness(int i, bool initial) const {
    Eigen::MatrixXd j;
    if (!m_setup->jacobian(initial ? Eigen::Vector3d::Zero().eval() : m_d, j).ok)
        return 0.0;
    const Eigen::Matrix3d k = initial ? m_specimen->initialTangent() : m_specimen->trialTangent();
    Eigen::FullPivLU<Eigen::Matrix3d> lu(k);
    if (!lu.isInvertible())
        return 0.0;
    const double c = (j * lu.solve(j.transpose()))(i, i);
    return c > 0.0 && std::isfinite(c) ? 1.0 / c : 0.0;
}

void SpecimenBehindSetup::commit() {
    m_specimen->commit();
    m_cd = m_d;
    m_cs = m_s;
    m_cf = m_f;
}

void SpecimenBehindSetup::revert() {
    m_specimen->revert();
    m_d = m_cd;
    m_s = m_cs;
    m_f = m_cf;
}

} // namespace hsmu
