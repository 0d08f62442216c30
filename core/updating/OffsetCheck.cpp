#include "core/updating/OffsetCheck.h"

#include "core/hysteresis/OffsetLaw.h"

#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

namespace hsmu {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The standard deviation of fitted parameter `name` (NaN: on its box or not fitted).
double sdOf(const CalibrationResult& r, const std::string& name)
{
    for (std::size_t i = 0; i < r.names.size(); ++i)
        if (r.names[i] == name && i < std::size_t(r.standardDeviation.size()))
            return r.standardDeviation[Eigen::Index(i)];
    return kNaN;
}
} // namespace

OffsetCheck::OffsetCheck(std::string law, CalibrationOffsets mode)
    : m_law(std::move(law)), m_mode(mode)
{
    if (mode == CalibrationOffsets::Off)
        throw std::invalid_argument("offset check: the offsets are off");
}

bool OffsetCheck::observe(int step, double time, double deformation, double force)
{
    m_u.push_back(deformation);
    m_f.push_back(force);
    m_t.push_back(time);
    const std::size_t n = m_u.size();
    bool proposed = false;
    if (m_job.due(n)) {
        auto taken = m_job.take();
        const CalibrationResult& r = taken.outcome;
        const auto u0 = r.parameters.find(OffsetLaw::kDeformationOffset);
        const auto f0 = r.parameters.find(OffsetLaw::kForceOffset);
        if (!r.ok)
            m_message = "offset check on " + std::to_string(taken.startSize) +
                        " samples failed: " + r.reason;
        else if (!r.offsetTest.used || u0 == r.parameters.end() || f0 == r.parameters.end())
            m_message = "offset check on " + std::to_string(taken.startSize) +
                        " samples: the data do not ask for offsets";
        else {
            OffsetProposal p;
            p.id = m_nextId++;
            p.step = step;
            p.time = time;
            p.deformationOffset = u0->second;
            p.forceOffset = f0->second;
            p.deformationSd = sdOf(r, OffsetLaw::kDeformationOffset);
            p.forceSd = sdOf(r, OffsetLaw::kForceOffset);
            p.nrmseWithout = r.offsetTest.nrmseWithout;
            p.nrmseWith = r.offsetTest.nrmseWith;
            p.branches = r.offsetTest.branches;
            p.criterion = r.offsetTest.criterion;
            p.samples = taken.startSize;
            m_pending = p; // supersedes the one still pending
            m_message.clear();
            proposed = true;
        }
    }
    if (!m_job.running() && n >= m_next) {
        m_next = 2 * n;
        CalibrationRequest request;
        request.law = m_law;
        request.offsets = m_mode;
        m_job.start(n, 0,
                    [u = m_u, f = m_f, t = m_t, request](const std::atomic<bool>& cancel) mutable {
                        request.cancel = &cancel;
                        request.time = std::move(t);
                        try {
                            return calibrateHistory(u, f, request);
                        } catch (const std::exception& e) {
                            CalibrationResult r;
                            r.reason = e.what();
                            return r;
                        }
                    });
    }
    return proposed;
}

std::optional<OffsetProposal> OffsetCheck::take(int id)
{
    if (!m_pending || m_pending->id != id)
        return std::nullopt;
    std::optional<OffsetProposal> p = std::move(m_pending);
    m_pending.reset();
    return p;
}

} // namespace hsmu
