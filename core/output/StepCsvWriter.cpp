#include "core/output/StepCsvWriter.h"

#include "core/output/TenDigits.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hsmu {

std::size_t StepCsvWriter::columnCount(const RunLayout& layout) {
    std::size_t n = 2 + 3 * layout.dofNames.size();
    for (const auto& e : layout.elements)
        n += e.experimental ? 3 : 2;
    if (layout.updating)
        n += 2 * layout.updating->parameters.size() + 2;
    return n + layout.channels.size();
}

std::vector<std::string> StepCsvWriter::columnNames(const RunLayout& layout) {
    std::vector<std::string> h{"time_s", "ag_m_s2"};
    for (const auto& d : layout.dofNames)
        for (const char* suffix : {"_u_m", "_v_m_s", "_a_m_s2"})
            h.push_back(d + suffix);
    for (const auto& e : layout.elements) {
        const std::string def = compactUnit(e.units.deformation);
        h.push_back(e.name + "_deformation_" + def);
        h.push_back(e.name + "_force_" + compactUnit(e.units.force));
        if (e.experimental)
            h.push_back(e.name + "_commanded_" + def);
    }
    if (layout.updating) {
        for (const auto& p : layout.updating->parameters)
            h.push_back("param_" + p);
        for (const auto& p : layout.updating->parameters)
            h.push_back("std_" + p);
        h.push_back("aux_force_" + compactUnit(layout.updating->units.force));
        h.push_back("fit_error");
    }
    for (const ElementChannel& c : layout.channels) {
        std::string name = c.element + "_" + c.name + "_" + compactUnit(c.unit);
        std::replace(name.begin(), name.end(), ' ', '_');
        h.push_back(name);
    }
    return h;
}

std::string StepCsvWriter::header(const RunLayout& layout) {
    std::string h;
    for (const std::string& name : columnNames(layout))
        h += (h.empty() ? "" : ",") + name;
    return h;
}

void StepCsvWriter::rowValues(const RunLayout& layout, const StepRecord& record,
                              std::vector<double>& out) {
    out.clear();
    out.push_back(record.time);
    out.push_back(record.groundAcceleration);
    for (std::size_t i = 0; i < layout.dofNames.size(); ++i) {
        const auto at = [i](const Eigen::VectorXd& x) {
            return Eigen::Index(i) < x.size() ? x[Eigen::Index(i)] : std::nan("");
        };
        out.push_back(at(record.u));
        out.push_back(at(record.v));
        out.push_back(at(record.a));
    }
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        const ElementSample s = i < record.elements.size() ? record.elements[i] : ElementSample{};
        out.push_back(s.deformation);
        out.push_back(s.force);
        if (layout.elements[i].experimental)
            out.push_back(s.commanded);
    }
    if (layout.updating)
        appendUpdating(layout, record, out);
    for (std::size_t i = 0; i < layout.channels.size(); ++i)
        out.push_back(i < record.channels.size() ? record.channels[i] : std::nan(""));
}

void StepCsvWriter::appendUpdating(const RunLayout& layout, const StepRecord& record,
                                   std::vector<double>& out) {
    const std::size_t n = layout.updating->parameters.size();
    const UpdatingSample& u = record.updating;
    const auto at = [&record](const std::vector<double>& x, std::size_t i) {
        return record.hasUpdating && i < x.size() ? x[i] : std::nan("");
    };
    for (std::size_t i = 0; i < n; ++i)
        out.push_back(at(u.parameters, i));
    for (std::size_t i = 0; i < n; ++i)
        out.push_back(at(u.stddev, i));
    out.push_back(record.hasUpdating ? u.auxiliaryForce : std::nan(""));
    out.push_back(record.hasUpdating ? u.fitError : std::nan(""));
}

StepCsvWriter::StepCsvWriter(const std::string& path, const RunLayout& layout)
    : m_path(path), m_layout(layout), m_out(path, std::ios::out | std::ios::trunc) {
    if (!m_out)
        throw std::runtime_error(path + ": cannot be opened for writing");
    m_out << header(m_layout) << '\n';
    m_buffer.resize(kBufferBytes + columnCount(m_layout) * (kTenDigitsMaxChars + 1) + 1);
}

StepCsvWriter::~StepCsvWriter() {
    finish();
}

void StepCsvWriter::onStep(const StepRecord& record) {
    if (!m_out.is_open())
        return;
    rowValues(m_layout, record, m_values);
    // Room for the row: each value and its separator within kTenDigitsMaxChars + 1 bytes.
    const std::size_t room = m_values.size() * (kTenDigitsMaxChars + 1) + 1;
    if (m_buffer.size() - m_used < room)
        m_buffer.resize(m_used + room);
    char* const row = m_buffer.data() + m_used;
    char* p = row;
    for (double v : m_values) {
        p = writeTenDigits(p, v);
        *p++ = ',';
    }
    p[-1] = '\n'; // the last separator ends the row
    m_used += std::size_t(p - row);
    const bool flush = ++m_rows % kFlushInterval == 0;
    if (flush || m_used >= kBufferBytes)
        writeBuffered(flush);
}

void StepCsvWriter::writeBuffered(bool flush) {
    m_out.write(m_buffer.data(), std::streamsize(m_used));
    m_used = 0;
    if (flush)
        m_out.flush();
    if (!m_out)
        m_failed = true;
}

bool StepCsvWriter::finish() {
    if (m_out.is_open()) {
        writeBuffered(true);
        m_out.close();
    }
    return !m_failed;
}

} // namespace hsmu
