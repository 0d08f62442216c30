#include "core/util/SecretFile.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sys/stat.h>

namespace hsmu {

bool checkPrivateFile(const std::string& path, const std::string& what, std::string& error) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        error = path + ": cannot read " + what;
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        error = path + ": " + what + " is not a regular file";
        return false;
    }
    if ((st.st_mode & 077) != 0) {
        char mode[8];
        std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
        error = path + ": " + what + " is readable by other users (mode " + mode +
                "); a secret others can read is no secret: chmod 600 " + path;
        return false;
    }
    return true;
}

std::optional<std::string> readSecretFile(const std::string& path, std::string& error) {
    std::ifstream in(path);
    if (!in) {
        error = path + ": cannot read the token file";
        return std::nullopt;
    }
    if (!checkPrivateFile(path, "the token file", error))
        return std::nullopt;
    std::string secret;
    std::getline(in, secret);
    while (!secret.empty() &&
           (secret.back() == '\r' || secret.back() == ' ' || secret.back() == '\t'))
        secret.pop_back();
    if (secret.empty() || secret.size() > 1024) {
        error = path + ": the token file's first line must hold a token of 1..1024 bytes";
        return std::nullopt;
    }
    return secret;
}

std::optional<std::string> linkToken(const std::string& tokenFile, std::string& error) {
    if (!tokenFile.empty())
        return readSecretFile(tokenFile, error);
    const char* env = std::getenv("HSMU_CONTROLLER_TOKEN");
    return std::string(env ? env : "");
}

} // namespace hsmu
