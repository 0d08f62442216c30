#include "core/config/TlsConfig.h"

#include "core/config/JsonCursor.h"
#include "core/util/SecretFile.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>

namespace hsmu {

std::optional<std::string> normalizeFingerprint(const std::string& text) {
    std::string t = text;
    for (const char* prefix : {"sha256:", "SHA256:", "sha256 Fingerprint=", "SHA256 Fingerprint="})
        if (t.rfind(prefix, 0) == 0)
            t = t.substr(std::string(prefix).size());
    std::string hex;
    for (const char ch : t) {
        if (ch == ':')
            continue;
        if (!std::isxdigit(static_cast<unsigned char>(ch)))
            return std::nullopt;
        hex.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(ch))));
    }
    if (hex.size() != 64)
        return std::nullopt;
    return hex;
}

bool readFingerprintFile(const std::string& path, std::vector<std::string>& out,
                         std::string& error) {
    std::ifstream in(path);
    if (!in) {
        error = path + ": cannot read the fingerprint list";
        return false;
    }
    int lineNo = 0;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        if (const auto hash = line.find('#'); hash != std::string::npos)
            line.erase(hash);
        line.erase(std::remove_if(line.begin(), line.end(),
                                  [](unsigned char c) { return std::isspace(c) != 0; }),
                   line.end());
        if (line.empty())
            continue;
        const auto fp = normalizeFingerprint(line);
        if (!fp) {
            error = path + ":" + std::to_string(lineNo) +
                    ": expected a SHA-256 fingerprint (64 hex digits, colons allowed)";
            return false;
        }
        out.push_back(*fp);
    }
    return true;
}

bool checkTlsSpec(const TlsSpec& spec, std::string& error) {
    if (spec.certificate.empty() || spec.key.empty()) {
        error = "TLS needs this end's certificate and key (a \"tls\" block with "
                "\"certificate\" and \"key\": docs/configuration.md, TLS)";
        return false;
    }
    if (spec.ca.empty() && spec.pins.empty() && spec.pinsFile.empty()) {
        error = "TLS needs a CA or pinned fingerprints to trust the other end";
        return false;
    }
    if (!spec.crl.empty() && spec.ca.empty()) {
        error = "a TLS CRL (" + spec.crl + ") needs the CA that signs it (\"ca\", --tls-ca)";
        return false;
    }
    for (const std::string* f :
         {&spec.ca, &spec.certificate, &spec.pinsFile, &spec.revokedFile, &spec.crl})
        if (!f->empty() && !std::ifstream(*f)) {
            error = *f + ": cannot read the file";
            return false;
        }
    return checkPrivateFile(spec.key, "the TLS key file", error);
}

TlsSpec parseTlsSpec(const JsonCursor& c, const std::string& baseDir) {
    c.requireObject();
    c.allowOnly({"ca", "certificate", "key", "pins", "revoked", "crl"});
    auto path = [&](const char* field) -> std::string {
        if (!c.has(field))
            return {};
        std::filesystem::path p = c.string(field);
        if (p.is_relative() && !baseDir.empty())
            p = std::filesystem::path(baseDir) / p;
        return p.string();
    };
    TlsSpec s;
    s.ca = path("ca");
    s.certificate = path("certificate");
    s.key = path("key");
    s.revokedFile = path("revoked");
    s.crl = path("crl");
    if (c.has("pins")) {
        const JsonCursor pins = c.child("pins");
        pins.requireArray();
        for (std::size_t i = 0; i < pins.size(); ++i) {
            const auto& v = pins.at(i).node();
            const auto fp = v.is_string() ? normalizeFingerprint(v.get<std::string>())
                                          : std::optional<std::string>();
            if (!fp)
                c.fail("pins", "expected SHA-256 fingerprints (64 hex digits, colons allowed)");
            s.pins.push_back(*fp);
        }
    }
    std::string error;
    if (!checkTlsSpec(s, error))
        c.fail(s.certificate.empty()            ? "certificate"
               : s.key.empty()                  ? "key"
               : s.ca.empty() && s.pins.empty() ? "ca"
                                                : "key",
               error);
    return s;
}

} // namespace hsmu
