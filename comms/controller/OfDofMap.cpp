#include "comms/controller/OfDofMap.h"

#include "core/config/JsonCursor.h"

#include <algorithm>
#include <cmath>

namespace hsmu::comms {

OfDofMap::OfDofMap(int specimens)
    : m_specimens(specimens), m_specimen(static_cast<std::size_t>(std::max(0, specimens))),
      m_factor(m_specimen.size(), 1.0) {
    for (std::size_t i = 0; i < m_specimen.size(); ++i)
        m_specimen[i] = static_cast<int>(i);
}

OfDofMap OfDofMap::parse(const nlohmann::json& controller, const std::vector<std::string>& names,
                         const std::string& file) {
    OfDofMap map(static_cast<int>(names.size()));
    if (!controller.is_object() || !controller.contains("serverDofs"))
        return map;
    const JsonCursor c(controller, file, "controller");
    const JsonCursor list = c.child("serverDofs");
    list.requireArray();
    if (list.size() == 0)
        c.fail("serverDofs", "at least one DOF");
    map.m_configured = true;
    map.m_specimen.assign(list.size(), -1);
    map.m_factor.assign(list.size(), 0.0);
    std::vector<bool> used(names.size(), false);
    for (std::size_t i = 0; i < list.size(); ++i) {
        const JsonCursor d = list.at(i);
        d.requireObject();
        d.allowOnly({"specimen", "factor"});
        if (!d.has("specimen"))
            continue; // a DOF without a specimen: zero force
        const std::string name = d.string("specimen");
        const auto it = std::find(names.begin(), names.end(), name);
        if (it == names.end()) {
            std::string known;
            for (const auto& n : names)
                known += (known.empty() ? "" : ", ") + ("'" + n + "'");
            d.fail("specimen",
                   "the name of an experimental element (" + known + "), not '" + name + "'");
        }
        const double f = d.number("factor", 1.0);
        if (!std::isfinite(f) || f == 0.0)
            d.fail("factor", "a finite non-zero number");
        map.m_specimen[i] = static_cast<int>(it - names.begin());
        map.m_factor[i] = f;
        used[static_cast<std::size_t>(it - names.begin())] = true;
    }
    for (std::size_t s = 0; s < names.size(); ++s)
        if (!used[s])
            c.fail("serverDofs",
                   "every experimental element on at least one DOF ('" + names[s] + "' has none)");
    return map;
}

std::string OfDofMap::describe() const {
    const auto plural = [](int k, const char* w) {
        return std::to_string(k) + " " + w + (k == 1 ? "" : "s");
    };
    if (!m_configured)
        return "1 DOF per specimen (" + plural(m_specimens, "specimen") + ")";
    return plural(dofs(), "DOF") + " from controller.serverDofs onto " +
           plural(m_specimens, "specimen");
}

std::vector<double> OfDofMap::deformations(const std::vector<double>& u) const {
    std::vector<double> d(static_cast<std::size_t>(m_specimens), 0.0);
    for (std::size_t i = 0; i < m_specimen.size() && i < u.size(); ++i)
        if (m_specimen[i] >= 0)
            d[static_cast<std::size_t>(m_specimen[i])] += m_factor[i] * u[i];
    return d;
}

std::vector<double> OfDofMap::forces(const std::vector<double>& f) const {
    std::vector<double> F(m_specimen.size(), 0.0);
    for (std::size_t i = 0; i < m_specimen.size(); ++i)
        if (m_specimen[i] >= 0)
            F[i] = m_factor[i] * f[static_cast<std::size_t>(m_specimen[i])];
    return F;
}

std::vector<double> OfDofMap::stiffness(const std::vector<double>& k) const {
    const std::size_t n = m_specimen.size();
    std::vector<double> K(n * n, 0.0);
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i)
            if (m_specimen[i] >= 0 && m_specimen[i] == m_specimen[j])
                K[j * n + i] =
                    m_factor[i] * m_factor[j] * k[static_cast<std::size_t>(m_specimen[i])];
    return K;
}

std::vector<double> OfDofMap::measuredDisp(const std::vector<double>& u,
                                           const std::vector<double>& dm,
                                           const std::vector<double>& dc) const {
    std::vector<double> norm2(static_cast<std::size_t>(m_specimens), 0.0);
    for (std::size_t i = 0; i < m_specimen.size(); ++i)
        if (m_specimen[i] >= 0)
            norm2[static_cast<std::size_t>(m_specimen[i])] += m_factor[i] * m_factor[i];
    std::vector<double> um = u;
    um.resize(m_specimen.size(), 0.0);
    for (std::size_t i = 0; i < m_specimen.size(); ++i)
        if (const int s = m_specimen[i]; s >= 0) {
            const auto k = static_cast<std::size_t>(s);
            um[i] += m_factor[i] * (dm[k] - dc[k]) / norm2[k];
        }
    return um;
}

} // namespace hsmu::comms
