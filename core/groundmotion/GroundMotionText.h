#pragma once
// GroundMotionText: internal helpers shared by the ground-motion readers (not a public API).
// Numbers are parsed with std::from_chars, so the process locale (which Qt sets from the
// environment) cannot turn "0.02" into 0 or 2.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hsmu::detail {

/// A text file split into lines ('\n' or "\r\n"); name is the file name used in messages.
struct TextFile {
    std::string name;
    std::string source;
    std::vector<std::string> lines;
};

/// Read the whole file; throws GroundMotionError if it is missing, a folder or unreadable.
TextFile readTextFile(const std::filesystem::path& path);

/// Parse a whole token as a number: optional sign, decimal or exponent form, Fortran 'D'
/// exponents accepted. "inf"/"nan" parse (the caller rejects non-finite values).
bool parseNumber(std::string_view token, double& value);

/// Split on any character of `separators` (empty fields are dropped).
std::vector<std::string_view> splitFields(std::string_view line, std::string_view separators);

/// The line without a '#' comment.
std::string_view stripComment(std::string_view line);

/// Upper-case copy (ASCII).
std::string toUpper(std::string_view text);

/// 'text' in quotes, shortened to about 40 characters, for error messages.
std::string excerpt(std::string_view text);

/// A number for a message with up to 10 significant digits, locale-independent.
std::string formatNumber(double value);

inline constexpr std::string_view kBlanks = " \t\r\f\v";
inline constexpr std::string_view kTextSeparators = " \t\r\f\v,;";

} // namespace hsmu::detail
