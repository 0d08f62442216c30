#include "core/groundmotion/GroundMotionText.h"

#include "core/groundmotion/GroundMotionError.h"
#include "core/util/InputLimits.h"

#include <cctype>
#include <charconv>
#include <fstream>
#include <sstream>
#include <system_error>

namespace hsmu::detail {

TextFile readTextFile(const std::filesystem::path& path) {
    TextFile file;
    file.name = path.filename().string();
    file.source = path.string();
    if (file.name.empty())
        file.name = file.source;

    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw GroundMotionError(file.name, 0,
                                "cannot open '" + file.source + "': the file does not exist");
    if (std::filesystem::is_directory(path, ec))
        throw GroundMotionError(file.name, 0,
                                "cannot open '" + file.source + "': it is a folder, not a file");
    if (!std::filesystem::is_regular_file(path, ec))
        throw GroundMotionError(file.name, 0,
                                "cannot read '" + file.source +
                                    "': not a regular file (a device, pipe or socket)");
    const auto size = std::filesystem::file_size(path, ec);
    if (ec || size > limits::kMaxTextFileBytes)
        throw GroundMotionError(file.name, 0,
                                "'" + file.source + "' is too large (" +
                                    (ec ? std::string("size unknown") : std::to_string(size) +
                                                                            " bytes") +
                                    ", at most " + std::to_string(limits::kMaxTextFileBytes) +
                                    " bytes)");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw GroundMotionError(file.name, 0,
                                "cannot open '" + file.source + "' for reading (permissions?)");
    std::string content;
    content.resize(static_cast<std::size_t>(size));
    in.read(content.data(), static_cast<std::streamsize>(content.size()));
    content.resize(static_cast<std::size_t>(in.gcount()));
    if (const std::size_t nul = content.find('\0'); nul != std::string::npos)
        throw GroundMotionError(file.name, 0,
                                "'" + file.source + "' is not a text file (binary data at byte " +
                                    std::to_string(nul) + ")");

    std::size_t start = 0;
    while (start < content.size()) {
        std::size_t end = content.find('\n', start);
        if (end == std::string::npos)
            end = content.size();
        std::string line = content.substr(start, end - start);
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        file.lines.push_back(std::move(line));
        start = end + 1;
    }
    return file;
}

bool parseNumber(std::string_view token, double& value) {
    if (!token.empty() && token.front() == '+')
        token.remove_prefix(1);
    if (token.empty() || token.front() == '+')
        return false;
    std::string text(token);
    for (char& c : text) {
        if (c == 'D' || c == 'd')
            c = 'E';
    }
    const char* first = text.data();
    const char* last = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(first, last, value);
    return ec == std::errc() && ptr == last;
}

std::vector<std::string_view> splitFields(std::string_view line, std::string_view separators) {
    std::vector<std::string_view> fields;
    std::size_t pos = 0;
    while (pos < line.size()) {
        const std::size_t begin = line.find_first_not_of(separators, pos);
        if (begin == std::string_view::npos)
            break;
        std::size_t end = line.find_first_of(separators, begin);
        if (end == std::string_view::npos)
            end = line.size();
        fields.push_back(line.substr(begin, end - begin));
        pos = end;
    }
    return fields;
}

std::string_view stripComment(std::string_view line) {
    const std::size_t hash = line.find('#');
    return hash == std::string_view::npos ? line : line.substr(0, hash);
}

std::string toUpper(std::string_view text) {
    std::string result(text);
    for (char& c : result)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return result;
}

std::string excerpt(std::string_view text) {
    const std::size_t begin = text.find_first_not_of(kBlanks);
    if (begin == std::string_view::npos)
        return "''";
    const std::size_t end = text.find_last_not_of(kBlanks);
    text = text.substr(begin, end - begin + 1);
    constexpr std::size_t kMax = 40;
    std::string result;
    result.reserve(kMax + 5);
    result += '\'';
    // Never echo raw bytes: control and non-ASCII characters become '?'.
    for (const char c : text.substr(0, kMax)) {
        const auto u = static_cast<unsigned char>(c);
        result += (u >= 0x20 && u < 0x7f) ? c : '?';
    }
    result += text.size() > kMax ? "...'" : "'";
    return result;
}

std::string formatNumber(double value) {
    char buffer[64];
    const auto [ptr, ec] =
        std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 10);
    if (ec != std::errc())
        return "?";
    return std::string(buffer, ptr);
}

} // namespace hsmu::detail
