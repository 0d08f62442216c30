#include "core/record/ActuatorColumns.h"

#include <cmath>

namespace hsmu {

namespace {

double channel(std::int64_t v) {
    return v < 0 ? std::nan("") : double(v);
}

} // namespace

void ActuatorColumns::create(hid_t elementsGroup, const std::vector<std::string>& names,
                             const std::vector<std::string>& deformationUnits,
                             const std::string& where, int deflate) {
    m_nElem = names.size();
    const h5::Id g =
        h5::check(H5Gcreate2(elementsGroup, "actuator", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                  where, "cannot create group /elements/actuator");
    const hid_t f64 = H5T_NATIVE_DOUBLE;
    const int n = int(m_nElem);
    const int rows = recordschema::kChunkRows;
    m_cmd = h5::Extendible(g.get(), "commanded", f64, n, where, rows, deflate);
    m_measured = h5::Extendible(g.get(), "measured", f64, n, where, rows, deflate);
    m_ticks = h5::Extendible(g.get(), "held_ticks", f64, n, where, rows, deflate);
    m_flags = h5::Extendible(g.get(), "flags", f64, n, where, rows, deflate);
    for (auto* d : {&m_cmd, &m_measured, &m_ticks, &m_flags})
        h5::writeAttr(d->id(), "names", names, where);
    h5::writeAttr(m_cmd.id(), "units", deformationUnits, where);
    h5::writeAttr(m_measured.id(), "units", deformationUnits, where);
}

void ActuatorColumns::buffer(const StepRecord& r, Rows& rows) const {
    for (std::size_t i = 0; i < m_nElem; ++i) {
        const ActuatorChannels c =
            i < r.elements.size() ? r.elements[i].actuator : ActuatorChannels{};
        rows.cmd.push_back(c.commanded);
        rows.measured.push_back(c.measured);
        rows.ticks.push_back(channel(c.heldTicks));
        rows.flags.push_back(channel(c.flags));
    }
}

void ActuatorColumns::write(const Rows& rows, hsize_t count) {
    if (count == 0 || rows.cmd.size() != count * m_nElem)
        return;
    m_cmd.append(rows.cmd.data(), count);
    m_measured.append(rows.measured.data(), count);
    m_ticks.append(rows.ticks.data(), count);
    m_flags.append(rows.flags.data(), count);
}

void ActuatorColumns::Rows::clear() {
    for (auto* b : {&cmd, &measured, &ticks, &flags})
        b->clear();
}

void ActuatorColumns::Rows::reserve(std::size_t values) {
    for (auto* b : {&cmd, &measured, &ticks, &flags})
        b->reserve(values);
}

void ActuatorColumns::close() {
    for (auto* d : {&m_cmd, &m_measured, &m_ticks, &m_flags})
        *d = h5::Extendible();
}

} // namespace hsmu
