#include "gui/cli/FastRun.h"

#include "core/config/PresetCatalog.h"
#include "core/config/RecordConfig.h"
#include "gui/NumberOverrides.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <unistd.h>

namespace hsmu::gui {

namespace {

/// A locale or language name that leaves the messages in English: C, POSIX, C.*, en, en_*.
bool englishName(const std::string& name) {
    if (name.empty() || name == "C" || name == "POSIX" || name.rfind("C.", 0) == 0)
        return true;
    return name.rfind("en", 0) == 0 &&
           (name.size() == 2 || name[2] == '_' || name[2] == '.' || name[2] == '@');
}

/// Every ':'-separated part of environment variable `var` is englishName (unset: true).
bool englishEnvironment(const char* var) {
    const char* value = std::getenv(var);
    if (!value)
        return true;
    std::string rest = value;
    for (std::size_t at = 0;;) {
        const std::size_t colon = rest.find(':', at);
        if (!englishName(rest.substr(at, colon - at)))
            return false;
        if (colon == std::string::npos)
            return true;
        at = colon + 1;
    }
}

std::string trimmed(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r");
    const auto e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// A QSettings INI file: false if it exists and sets [General] language to a non-English
/// code, or cannot be read.
bool englishSettingsFile(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return !ec;
    std::ifstream in(path);
    if (!in)
        return false;
    std::string line, section;
    while (std::getline(in, line)) {
        line = trimmed(line);
        if (!line.empty() && line.front() == '[') {
            section = line;
            continue;
        }
        const auto eq = line.find('=');
        if (eq == std::string::npos || trimmed(line.substr(0, eq)) != "language")
            continue;
        std::string value = trimmed(line.substr(eq + 1));
        if (value.size() >= 2 && value.front() == '"' && value.back() == '"')
            value = value.substr(1, value.size() - 2);
        if ((section.empty() || section == "[General]") && !englishName(value))
            return false;
    }
    return true;
}

/// The whole text as a finite double (std::from_chars: no sign '+', no spaces).
std::optional<double> finite(const std::string& text) {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

std::optional<int> whole(const std::string& text) {
    int v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return v;
}

} // namespace

bool FastRun::englishOnly() {
    for (const char* var : {"LANGUAGE", "LC_ALL", "LC_MESSAGES", "LANG"})
        if (!englishEnvironment(var))
            return false;
    // QSettings("HSMU", "hsmu")'s files: the user's, then each XDG_CONFIG_DIRS one.
    std::vector<std::string> dirs;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x)
        dirs.emplace_back(x);
    else if (const char* home = std::getenv("HOME"))
        dirs.push_back(std::string(home) + "/.config");
    else
        return false;
    const char* system = std::getenv("XDG_CONFIG_DIRS");
    const std::string systemDirs = system && *system ? system : "/etc/xdg";
    for (std::size_t at = 0;;) {
        const std::size_t colon = systemDirs.find(':', at);
        dirs.push_back(systemDirs.substr(at, colon - at));
        if (colon == std::string::npos)
            break;
        at = colon + 1;
    }
    for (const std::string& dir : dirs)
        if (!englishSettingsFile(dir + "/HSMU/hsmu.conf") ||
            !englishSettingsFile(dir + "/HSMU.conf"))
            return false;
    return true;
}

std::optional<RunRequest> FastRun::request(int argc, char** argv) {
    if (argc < 2 || std::strcmp(argv[1], "run") != 0 || std::getenv("HSMU_CONTROLLER_TOKEN"))
        return std::nullopt;
    static const char* const kValued[] = {"out",         "scale",       "dt",       "duration",
                                          "record-dt",   "csv",         "compress", "reconnect",
                                          "record-dofs", "record-every"};
    std::map<std::string, std::string> values;
    bool allowUnstable = false;
    std::string config;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--allow-unstable") {
            if (allowUnstable)
                return std::nullopt;
            allowUnstable = true;
            continue;
        }
        if (a.rfind("--", 0) == 0) {
            const std::size_t eq = a.find('=');
            const std::string name = a.substr(2, eq == std::string::npos ? eq : eq - 2);
            if (std::find_if(std::begin(kValued), std::end(kValued),
                             [&name](const char* k) { return name == k; }) == std::end(kValued))
                return std::nullopt;
            if (values.count(name) || (eq == std::string::npos && i + 1 >= argc))
                return std::nullopt;
            values[name] = eq == std::string::npos ? std::string(argv[++i]) : a.substr(eq + 1);
            continue;
        }
        if (a.empty() || a.front() == '-' || !config.empty())
            return std::nullopt;
        config = a;
    }
    std::error_code ec;
    if (config.empty() || !std::filesystem::is_regular_file(config, ec) || values["out"].empty())
        return std::nullopt;

    NumberOverrides numbers;
    numbers.allowUnstable = allowUnstable;
    const struct {
        const char* name;
        std::optional<double>& target;
        bool positive;
    } numeric[] = {{"record-dt", numbers.recordDt, true},
                   {"scale", numbers.scale, false},
                   {"dt", numbers.dt, true},
                   {"duration", numbers.duration, true}};
    for (const auto& n : numeric) {
        const auto it = values.find(n.name);
        if (it == values.end())
            continue;
        const auto v = finite(it->second);
        if (!v || (n.positive && *v <= 0.0))
            return std::nullopt;
        n.target = *v;
    }
    RunRequest r;
    r.config = config;
    r.outDir = values["out"];
    r.presets.ids = [] { return std::vector<std::string>{}; };
    r.presets.text = [](const std::string&) { return std::optional<std::string>(); };
    r.configure = [numbers](TestConfig& cfg) { numbers.applyTo(cfg); };
    const std::string csv = values.count("csv") ? values["csv"] : "auto";
    if (csv != "auto" && csv != "all" && csv != "none")
        return std::nullopt;
    r.csv = csv == "none"  ? HeadlessOptions::Csv::None
            : csv == "all" ? HeadlessOptions::Csv::All
                           : HeadlessOptions::Csv::Auto;
    const auto deflate = whole(values.count("compress") ? values["compress"] : "0");
    const auto reconnect = whole(values.count("reconnect") ? values["reconnect"] : "0");
    if (!deflate || *deflate < 0 || *deflate > 9 || !reconnect || *reconnect < 0)
        return std::nullopt;
    r.deflate = *deflate;
    r.reconnect = *reconnect;
    if (values.count("record-dofs")) // checked against the configuration by RunFlow
        r.recordDofs = values["record-dofs"];
    if (values.count("record-every")) { // a bad value: hsmu-cli says what is wrong
        const auto every = whole(values["record-every"]);
        if (!every || *every < 1 || *every > kMaxRecordEvery)
            return std::nullopt;
        r.recordEvery = *every;
    }
    if (!englishOnly())
        return std::nullopt;
    return r; // controller: builtin (LinkAddress's default), no token, no approval
}

int FastRun::guarded(const std::function<int()>& body) {
    try {
        return body();
    } catch (const std::exception& e) { // last line of defence: a message, never an abort
        std::fprintf(stderr, "hsmu: internal error: %s\n", e.what());
    } catch (...) {
        std::fputs("hsmu: internal error\n", stderr);
    }
    return 1;
}

std::pair<std::string, int> FastRun::execSibling(const char* name, char** argv, const char* argv0) {
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const std::string path =
        ((ec ? std::filesystem::path(argv[0]).parent_path() : self.parent_path()) / name).string();
    std::string first = argv0 ? argv0 : argv[0];
    if (argv0)
        argv[0] = first.data();
    ::execv(path.c_str(), argv);
    return {path, errno};
}

int FastRun::main(int argc, char** argv) {
    return guarded([argc, argv] {
        if (auto r = request(argc, argv))
            return RunFlow::exec(*r);
        const auto [path, error] = execSibling("hsmu-cli", argv, nullptr);
        std::fprintf(stderr,
                     "hsmu: cannot start %s: %s (the subcommands other than a plain "
                     "`hsmu run FILE` run in it)\n",
                     path.c_str(), std::strerror(error));
        return 1;
    });
}

} // namespace hsmu::gui
