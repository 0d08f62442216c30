#include "core/output/RunStatistics.h"

#include <cmath>

namespace hsmu {

namespace {
void keepPeak(double& peak, double value) {
    if (std::isfinite(value) && std::abs(value) > peak)
        peak = std::abs(value);
}
} // namespace

RunStatistics::RunStatistics(RunLayout layout)
    : m_layout(std::move(layout)), m_peakU(m_layout.dofNames.size(), 0.0),
      m_peakForce(m_layout.elements.size(), 0.0), m_peakDeformation(m_layout.elements.size(), 0.0),
      m_peakChannel(m_layout.channels.size(), 0.0),
      m_commanded(m_layout.elements.size()), m_measured(m_layout.elements.size()),
      m_tracking(m_layout.elements.size()) {
}

const rths::TrackingReport* RunStatistics::tracking(std::size_t i, double dt) const {
    if (m_commanded[i].size() < 2)
        return nullptr;
    if (!m_tracking[i])
        m_tracking[i] = rths::trackingReport(m_commanded[i], m_measured[i], dt);
    return &*m_tracking[i];
}

void RunStatistics::onStep(const StepRecord& record) {
    ++m_count;
    m_last = record;
    keepPeak(m_peakAg, record.groundAcceleration);
    for (std::size_t i = 0; i < m_peakU.size() && Eigen::Index(i) < record.u.size(); ++i)
        keepPeak(m_peakU[i], record.u[Eigen::Index(i)]);
    for (std::size_t i = 0; i < m_peakChannel.size() && i < record.channels.size(); ++i)
        keepPeak(m_peakChannel[i], record.channels[i]);
    for (std::size_t i = 0; i < m_peakForce.size() && i < record.elements.size(); ++i) {
        keepPeak(m_peakForce[i], record.elements[i].force);
        keepPeak(m_peakDeformation[i], record.elements[i].deformation);
        const ElementSample& e = record.elements[i];
        if (record.step > 0 && m_layout.elements[i].experimental && std::isfinite(e.commanded) &&
            std::isfinite(e.deformation)) {
            m_commanded[i].push_back(e.commanded);
            m_measured[i].push_back(e.deformation);
        }
    }
}

} // namespace hsmu
