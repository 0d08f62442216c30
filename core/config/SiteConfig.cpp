#include "core/config/SiteConfig.h"
#include "core/util/SecretFile.h"

#include "core/config/JsonCursor.h"
#include "core/config/TestConfig.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace hsmu {

namespace {

std::optional<double> seconds(const JsonCursor& c, const char* key) {
    if (!c.has(key))
        return std::nullopt;
    const double v = c.number(key);
    if (!(v > 0.0) || !(v <= 3600.0))
        c.fail(key, "expected seconds in (0, 3600]");
    return v;
}

std::string readToken(const JsonCursor& c, const std::string& path) {
    std::string error;
    const auto token = readSecretFile(path, error);
    if (!token)
        c.fail("tokenFile", error);
    return *token;
}

} // namespace

std::vector<SiteSpec> parseSites(const JsonCursor& root, const std::string& baseDir,
                                 const LinkSpec& defaults, std::vector<ElementSpec>& elements) {
    std::vector<SiteSpec> sites;
    if (!root.has("sites"))
        return sites;
    const JsonCursor list = root.child("sites");
    list.requireArray();
    if (list.size() > 256)
        list.fail("", "at most 256 sites");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const JsonCursor c = list.at(i);
        c.requireObject();
        c.allowOnly({"name", "address", "elements", "protocol", "dataSize", "ctrlSizes",
                     "daqSizes", "initFile", "tokenFile", "connectTimeout", "stepDeadline", "tls"});
        SiteSpec s;
        s.name = c.string("name");
        if (s.name.empty() || s.name.size() > 64)
            c.fail("name", "a site name of 1..64 characters");
        if (s.name == kDefaultSiteName)
            c.fail("name", std::string("'") + kDefaultSiteName +
                               "' is the site of the elements no site lists; choose another name");
        for (const SiteSpec& other : sites)
            if (other.name == s.name)
                c.fail("name", "two sites are named '" + s.name + "'");
        s.address = c.string("address");
        if (s.address != "builtin" && s.address.find("://") == std::string::npos)
            c.fail("address", "expected builtin, tcp://HOST:PORT, simapp://HOST:PORT, "
                              "generictcp://HOST:PORT or adapter://HOST:PORT, found '" +
                                  s.address + "'");
        s.link = parseLinkFields(c, baseDir, defaults);
        if (c.has("tls")) // the site's own certificates instead of the top-level block
            s.link.tls = parseTlsSpec(c.child("tls"), baseDir);
        if (c.has("tokenFile")) {
            std::filesystem::path p = c.string("tokenFile");
            if (p.is_relative() && !baseDir.empty())
                p = std::filesystem::path(baseDir) / p;
            s.tokenFile = p.string();
            s.token = readToken(c, s.tokenFile);
        }
        s.connectTimeout = seconds(c, "connectTimeout");
        s.stepDeadline = seconds(c, "stepDeadline");
        const JsonCursor names = c.child("elements");
        names.requireArray();
        if (names.size() == 0)
            c.fail("elements", "expected the names of the experimental elements the site serves");
        for (std::size_t k = 0; k < names.size(); ++k) {
            const nlohmann::json& v = names.node()[k];
            if (!v.is_string())
                c.fail("elements", "expected element names (strings)");
            const std::string name = v.get<std::string>();
            auto e = std::find_if(elements.begin(), elements.end(),
                                  [&](const ElementSpec& x) { return x.name == name; });
            if (e == elements.end())
                c.fail("elements", "no element named '" + name + "'");
            if (!e->experimental)
                c.fail("elements", "'" + name + "' is numerical; only experimental elements "
                                                "are served by a site");
            if (!e->site.empty())
                c.fail("elements", "'" + name + "' is already served by site '" + e->site + "'");
            e->site = s.name;
            s.elements.push_back(name);
        }
        sites.push_back(std::move(s));
    }
    return sites;
}

} // namespace hsmu
