#pragma once
// LogText: a peer's text made fit for one log line (issue 26, D2). What a client sends (an
// OpenFresco init line, a hello's element name) may hold CR/LF that would start a forged log
// line, terminal escape sequences or binary bytes, and may be long: printable ASCII is kept,
// '\' and every other byte are written as escapes (\r, \n, \t, \\, \xNN), and the result is
// cut after maxBytes of input with "... (N bytes)". Thread rules: none (pure).

#include <cstddef>
#include <string>
#include <string_view>

namespace hsmu::comms {

std::string logText(std::string_view text, std::size_t maxBytes = 200);

} // namespace hsmu::comms
