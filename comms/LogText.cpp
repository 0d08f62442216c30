#include "comms/LogText.h"

#include <cstdio>

namespace hsmu::comms {

std::string logText(std::string_view text, std::size_t maxBytes) {
    std::string out;
    const std::size_t n = std::min(text.size(), maxBytes);
    out.reserve(n + 24);
    for (std::size_t i = 0; i < n; ++i) {
        const auto u = static_cast<unsigned char>(text[i]);
        if (u == '\\')
            out += "\\\\";
        else if (u >= 0x20 && u < 0x7f)
            out += static_cast<char>(u);
        else if (u == '\r')
            out += "\\r";
        else if (u == '\n')
            out += "\\n";
        else if (u == '\t')
            out += "\\t";
        else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", u);
            out += hex;
        }
    }
    if (text.size() > n)
        out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

} // namespace hsmu::comms
