#pragma once
// SecretFile: reads a shared secret (a link token) from a file, the one way every program
// here takes one (hsmu-controller --token-file, hsmu run --token-file, a site's tokenFile).
// The secret is the file's first line without trailing CR and blanks, 1..1024 bytes. Like
// ssh with its keys, a file that other users can read or write (any group or other
// permission bit) is refused with the command that fixes it (issue 26, D3): a secret that
// others can read is no secret. No Qt; thread rules: none.

#include <optional>
#include <string>

namespace hsmu {

/// The secret of path, or nullopt with a sentence naming path in error.
std::optional<std::string> readSecretFile(const std::string& path, std::string& error);

/// A link's token as every program takes it (docs/security.md): the secret of tokenFile when
/// one is named, else the environment variable HSMU_CONTROLLER_TOKEN, else "" (none). nullopt
/// with readSecretFile's sentence in error when the named file is refused.
std::optional<std::string> linkToken(const std::string& tokenFile, std::string& error);

/// The same rule for any private file (a TLS key: what = "the TLS key file"): true when path
/// is a regular file that only its owner may read or write; otherwise false with a sentence
/// naming path and what in error (the chmod that fixes it).
bool checkPrivateFile(const std::string& path, const std::string& what, std::string& error);

} // namespace hsmu
