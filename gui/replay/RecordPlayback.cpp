#include "gui/replay/RecordPlayback.h"

#include <algorithm>
#include <cmath>

namespace hsmu::gui {

RecordPlayback::RecordPlayback(std::shared_ptr<const RecordData> data) : m_data(std::move(data)) {}

StepRecord RecordPlayback::rowAt(const RecordData& d, int i) {
    StepRecord r;
    r.step = d.steps[std::size_t(i)];
    r.time = d.time(i);
    r.groundAcceleration = d.groundAcceleration(i);
    if (d.meta.dofRecording.full()) {
        r.u = d.u.row(i).transpose();
        r.v = d.v.row(i).transpose();
        r.a = d.a.row(i).transpose();
    } else { // chosen or decimated DOFs: NaN where the record has no value
        const auto n = Eigen::Index(d.layout.dofNames.size());
        r.u = Eigen::VectorXd::Constant(n, std::nan(""));
        r.v = r.u;
        r.a = r.u;
        if (const int k = d.dofRowOf(i); k >= 0)
            for (Eigen::Index j = 0; j < d.u.cols(); ++j) {
                const Eigen::Index dof = d.dofIndex(int(j));
                r.u[dof] = d.u(k, j);
                r.v[dof] = d.v(k, j);
                r.a[dof] = d.a(k, j);
            }
    }
    r.elements.resize(std::size_t(d.deformation.cols()));
    for (Eigen::Index j = 0; j < d.deformation.cols(); ++j) {
        ElementSample& e = r.elements[std::size_t(j)];
        e.deformation = d.deformation(i, j);
        e.force = d.force(i, j);
        e.commanded = d.commanded(i, j);
        if (i < d.actuatorCommanded.rows() && j < d.actuatorCommanded.cols()) {
            e.actuator.commanded = d.actuatorCommanded(i, j);
            e.actuator.measured = d.actuatorMeasured(i, j);
            e.actuator.heldTicks =
                std::isnan(d.heldTicks(i, j)) ? -1 : std::int64_t(d.heldTicks(i, j));
            e.actuator.flags =
                std::isnan(d.actuatorFlags(i, j)) ? -1 : std::int64_t(d.actuatorFlags(i, j));
        }
    }
    if (i < d.channels.rows()) // the multi-DOF elements' channels (/elements/channels)
        r.channels.assign(d.channels.row(i).begin(), d.channels.row(i).end());
    r.hasUpdating = d.layout.updating.has_value() && d.parameters.rows() > i;
    if (r.hasUpdating) {
        UpdatingSample& u = r.updating;
        u.auxiliaryForce = d.auxiliaryForce(i);
        u.fitError = d.fitError(i);
        for (Eigen::Index j = 0; j < d.parameters.cols(); ++j) {
            u.parameters.push_back(d.parameters(i, j));
            u.stddev.push_back(j < d.stddev.cols() ? d.stddev(i, j) : 0.0);
        }
        u.appliedUpdates = d.appliedUpdates[std::size_t(i)];
        u.updatesThisStep = d.updatesThisStep[std::size_t(i)];
        u.pendingProposals = d.pendingProposals[std::size_t(i)];
    }
    return r;
}

double RecordPlayback::time() const {
    return m_shown > 0 ? m_data->time(m_shown - 1) : 0.0;
}

int RecordPlayback::step() const {
    return m_shown > 0 ? m_data->steps[std::size_t(m_shown - 1)] : -1;
}

void RecordPlayback::setSpeed(double factor) {
    if (std::isfinite(factor) && factor > 0.0)
        m_speed = factor;
}

std::vector<StepRecord> RecordPlayback::advance(double wallSeconds) {
    if (atEnd())
        return {};
    if (m_shown == 0) // the initial state appears at once
        m_playTime = m_data->time(0);
    else
        m_playTime = std::max(m_playTime, time());
    m_playTime += m_speed * std::max(0.0, wallSeconds);
    int to = m_shown;
    while (to < rows() && (to == 0 || m_data->time(to) <= m_playTime + 1e-12))
        ++to;
    const int from = m_shown;
    m_shown = to;
    return take(from, to);
}

std::vector<StepRecord> RecordPlayback::seek(int n, bool* restart) {
    n = std::clamp(n, 0, rows());
    const bool back = n < m_shown;
    if (restart)
        *restart = back;
    const int from = back ? 0 : m_shown;
    m_shown = n;
    m_playTime = time();
    return take(from, n);
}

std::vector<StepRecord> RecordPlayback::take(int from, int to) const {
    std::vector<StepRecord> out;
    out.reserve(std::size_t(std::max(0, to - from)));
    for (int i = from; i < to; ++i)
        out.push_back(rowAt(*m_data, i));
    return out;
}

} // namespace hsmu::gui
