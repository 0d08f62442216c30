#include "core/record/CsvText.h"

#include <charconv>
#include <cmath>

namespace hsmu::csvtext {

std::string number(double x) {
    if (std::isnan(x))
        return "nan";
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x);
    return std::string(buf, r.ptr);
}

std::string quoted(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
    std::string q = "\"";
    for (char c : text) {
        if (c == '"')
            q += '"';
        q += c;
    }
    return q + '"';
}

std::string column(const std::string& name, const std::string& unit) {
    return quoted(unit.empty() ? name : name + " [" + unit + "]");
}

std::string join(const std::vector<std::string>& fields) {
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i)
            line += ',';
        line += fields[i];
    }
    return line;
}

} // namespace hsmu::csvtext
