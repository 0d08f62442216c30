#include "core/record/CsvFile.h"

#include "core/record/CsvText.h"

#include <stdexcept>

namespace hsmu {

CsvFile::CsvFile(const std::string& path, std::vector<std::string>& written)
    : m_path(path), m_out(path) {
    if (!m_out)
        throw std::runtime_error(m_path + ": cannot be written");
    written.push_back(m_path);
}

void CsvFile::column(const std::string& name, const std::string& unit) {
    m_header.push_back(csvtext::column(name, unit));
}

void CsvFile::endHeader() {
    line(m_header);
}

void CsvFile::line(const std::vector<std::string>& fields) {
    m_out << csvtext::join(fields) << '\n';
}

void CsvFile::close() {
    m_out.close();
    if (!m_out)
        throw std::runtime_error(m_path + ": write failed");
}

} // namespace hsmu
