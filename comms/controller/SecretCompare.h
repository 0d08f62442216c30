#pragma once
// sameSecret: the hello's token against the controller's, in a time that does not depend on
// where the texts first differ (ControllerServer, RthsServer). An empty expected token never
// matches (the caller skips the check when it has none).

#include <algorithm>
#include <string>

namespace hsmu::comms {

inline bool sameSecret(const std::string& given, const std::string& expected) {
    unsigned char diff = given.size() == expected.size() ? 0 : 1;
    for (std::size_t i = 0; i < given.size(); ++i)
        diff |= static_cast<unsigned char>(
            given[i] ^ expected[i % std::max<std::size_t>(expected.size(), 1)]);
    return diff == 0 && !expected.empty();
}

} // namespace hsmu::comms
