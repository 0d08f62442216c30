#include "core/output/StepCsvWriter.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace hsmu {

namespace {

void appendValue(std::string& line, double value) {
    char buf[32];
    // std::to_chars is locale-independent; general format with 10 digits equals "%.10g".
    const auto r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 10);
    line.push_back(',');
    line.append(buf, r.ptr);
}

} // namespace

std::size_t StepCsvWriter::columnCount(const RunLayout& layout) {
    std::size_t n = 2 + 3 * layout.dofNames.size();
    for (const auto& e : layout.elements)
        n += e.experimental ? 3 : 2;
    if (layout.updating)
        n += 2 * layout.updating->parameters.size() + 2;
    return n;
}

std::string StepCsvWriter::header(const RunLayout& layout) {
    std::string h = "time_s,ag_m_s2";
    for (const auto& d : layout.dofNames)
        h += "," + d + "_u_m," + d + "_v_m_s," + d + "_a_m_s2";
    for (const auto& e : layout.elements) {
        const std::string def = compactUnit(e.units.deformation);
        h += "," + e.name + "_deformation_" + def + "," + e.name + "_force_" +
             compactUnit(e.units.force);
        if (e.experimental)
            h += "," + e.name + "_commanded_" + def;
    }
    if (layout.updating) {
        for (const auto& p : layout.updating->parameters)
            h += ",param_" + p;
        for (const auto& p : layout.updating->parameters)
            h += ",std_" + p;
        h += ",aux_force_" + compactUnit(layout.updating->units.force) + ",fit_error";
    }
    return h;
}

StepCsvWriter::StepCsvWriter(const std::string& path, const RunLayout& layout)
    : m_path(path), m_layout(layout), m_out(path, std::ios::out | std::ios::trunc) {
    if (!m_out)
        throw std::runtime_error(path + ": cannot be opened for writing");
    m_out << header(m_layout) << '\n';
}

StepCsvWriter::~StepCsvWriter() {
    finish();
}

void StepCsvWriter::onStep(const StepRecord& record) {
    if (!m_out.is_open())
        return;
    m_line.clear();
    appendValue(m_line, record.time);
    m_line.erase(0, 1); // no leading comma
    appendValue(m_line, record.groundAcceleration);
    for (std::size_t i = 0; i < m_layout.dofNames.size(); ++i) {
        const auto at = [i](const Eigen::VectorXd& x) {
            return Eigen::Index(i) < x.size() ? x[Eigen::Index(i)] : std::nan("");
        };
        appendValue(m_line, at(record.u));
        appendValue(m_line, at(record.v));
        appendValue(m_line, at(record.a));
    }
    for (std::size_t i = 0; i < m_layout.elements.size(); ++i) {
        const ElementSample s = i < record.elements.size() ? record.elements[i] : ElementSample{};
        appendValue(m_line, s.deformation);
        appendValue(m_line, s.force);
        if (m_layout.elements[i].experimental)
            appendValue(m_line, s.commanded);
    }
    if (m_layout.updating)
        appendUpdating(record);
    m_line.push_back('\n');
    m_out.write(m_line.data(), std::streamsize(m_line.size()));
    if (++m_rows % kFlushInterval == 0)
        m_out.flush();
    if (!m_out)
        m_failed = true;
}

void StepCsvWriter::appendUpdating(const StepRecord& record) {
    const std::size_t n = m_layout.updating->parameters.size();
    const UpdatingSample& u = record.updating;
    const auto at = [&record](const std::vector<double>& x, std::size_t i) {
        return record.hasUpdating && i < x.size() ? x[i] : std::nan("");
    };
    for (std::size_t i = 0; i < n; ++i)
        appendValue(m_line, at(u.parameters, i));
    for (std::size_t i = 0; i < n; ++i)
        appendValue(m_line, at(u.stddev, i));
    appendValue(m_line, record.hasUpdating ? u.auxiliaryForce : std::nan(""));
    appendValue(m_line, record.hasUpdating ? u.fitError : std::nan(""));
}

bool StepCsvWriter::finish() {
    if (m_out.is_open()) {
        m_out.flush();
        if (!m_out)
            m_failed = true;
        m_out.close();
    }
    return !m_failed;
}

} // namespace hsmu
