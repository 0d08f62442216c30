#pragma once
// CsvFile: one CSV file written by our exports: a header line of "name [unit]" columns, then
// rows of fields already formatted (CsvText.h). Throws std::runtime_error naming the file
// when it cannot be created or a write failed (close()).
// Thread rules: one thread.

#include <fstream>
#include <string>
#include <vector>

namespace hsmu {

class CsvFile {
public:
    /// Creates (truncates) path and appends it to `written`.
    CsvFile(const std::string& path, std::vector<std::string>& written);
    void column(const std::string& name, const std::string& unit);
    void endHeader();
    void line(const std::vector<std::string>& fields);
    void close();

private:
    std::string m_path;
    std::ofstream m_out;
    std::vector<std::string> m_header;
};

} // namespace hsmu
