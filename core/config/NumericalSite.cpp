#include "core/config/NumericalSite.h"

#include <charconv>
#include <mutex>

namespace hsmu {

namespace {

std::mutex& factoryMutex()
{
    static std::mutex m;
    return m;
}

NumericalSiteFactory& factorySlot()
{
    static NumericalSiteFactory f;
    return f;
}

} // namespace

bool parseNumericalSite(const std::string& text, NumericalSiteAddress& out, std::string& why)
{
    const std::string prefix = "opensees://";
    if (text.rfind(prefix, 0) != 0) {
        why = "expected opensees://HOST:PORT, found '" + text + "'";
        return false;
    }
    const std::string rest = text.substr(prefix.size());
    const auto colon = rest.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == rest.size()) {
        why = "expected opensees://HOST:PORT, found '" + text + "'";
        return false;
    }
    unsigned port = 0;
    const char* first = rest.data() + colon + 1;
    const char* last = rest.data() + rest.size();
    const auto [end, ec] = std::from_chars(first, last, port);
    if (ec != std::errc{} || end != last || port == 0 || port > 65535) {
        why = "expected a port 1-65535 in '" + text + "'";
        return false;
    }
    out.scheme = "opensees";
    out.host = rest.substr(0, colon);
    out.port = static_cast<std::uint16_t>(port);
    return true;
}

std::string numericalSiteProblem(const std::string& text)
{
    NumericalSiteAddress a;
    std::string why;
    return parseNumericalSite(text, a, why) ? std::string{} : why;
}

void setNumericalSiteFactory(NumericalSiteFactory factory)
{
    std::lock_guard lock(factoryMutex());
    factorySlot() = std::move(factory);
}

NumericalSiteFactory numericalSiteFactory()
{
    std::lock_guard lock(factoryMutex());
    return factorySlot();
}

} // namespace hsmu
