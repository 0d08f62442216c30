#include "core/util/Units.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <numbers>

namespace hsmu::units {

namespace {

struct Entry {
    const char* symbol;
    double factor;
};

constexpr double kLbf = 4.4482216152605e-3; // kN: 0.45359237 kg * 9.80665 m/s^2
constexpr double kKgf = 9.80665e-3;         // kN

constexpr std::array<Entry, 5> kLength{{{"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254},
                                        {"ft", 0.3048}}};
constexpr std::array<Entry, 7> kForce{{{"N", 1e-3},
                                       {"kN", 1.0},
                                       {"MN", 1e3},
                                       {"lbf", kLbf},
                                       {"kip", 1000.0 * kLbf},
                                       {"kgf", kKgf},
                                       {"tonf", 1000.0 * kKgf}}};
constexpr std::array<Entry, 3> kRotation{{{"rad", 1.0},
                                          {"mrad", 1e-3},
                                          {"deg", std::numbers::pi / 180.0}}};
constexpr std::array<Entry, 2> kTime{{{"s", 1.0}, {"ms", 1e-3}}};

std::string lower(std::string_view s) {
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

std::string_view trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) {
        return {};
    }
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

// Spellings in common use read as a symbol of the tables (the US plural "kips").
std::string canonical(std::string key) {
    return key == "kips" ? std::string("kip") : key;
}

// Letter case is ignored, except that "mN" (the millinewton, not supported) is never read as
// the meganewton MN.
template <std::size_t N>
std::optional<Entry> find(const std::array<Entry, N>& table, std::string_view text) {
    const std::string_view t = trim(text);
    const std::string key = canonical(lower(t));
    for (const Entry& e : table) {
        if (key == lower(e.symbol) && !(e.symbol[0] == 'M' && t[0] == 'm')) {
            return e;
        }
    }
    return std::nullopt;
}

template <std::size_t N>
std::optional<Unit> simple(const std::array<Entry, N>& table, std::string_view text, Dimension d) {
    if (const auto e = find(table, text)) {
        return Unit{e->symbol, d, e->factor};
    }
    return std::nullopt;
}

// "kN m", "kN*m", "kN.m", "kN-m", "kN·m" (U+00B7) or "kNm": a force unit and a length unit.
std::optional<Unit> moment(std::string_view text) {
    std::string compact;
    const std::string_view t = trim(text);
    for (std::size_t i = 0; i < t.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(t[i]);
        if (c == 0xC2 && i + 1 < t.size() && static_cast<unsigned char>(t[i + 1]) == 0xB7) {
            ++i;
            continue;
        }
        if (c == ' ' || c == '*' || c == '.' || c == '-' || c == '\t') {
            continue;
        }
        compact.push_back(static_cast<char>(c));
    }
    // Every split into a force prefix and a length suffix; at most one can match (the force
    // symbols do not end in a length symbol's prefix).
    for (std::size_t split = 1; split < compact.size(); ++split) {
        const auto f = find(kForce, std::string_view(compact).substr(0, split));
        const auto l = find(kLength, std::string_view(compact).substr(split));
        if (f && l) {
            return Unit{std::string(f->symbol) + " " + l->symbol, Dimension::Moment,
                        f->factor * l->factor};
        }
    }
    return std::nullopt;
}

template <std::size_t N> std::string list(const std::array<Entry, N>& table) {
    std::string out;
    for (const Entry& e : table) {
        out += out.empty() ? e.symbol : std::string(", ") + e.symbol;
    }
    return out;
}

} // namespace

std::optional<Unit> parse(std::string_view text, Dimension d) {
    switch (d) {
    case Dimension::Length:
        return simple(kLength, text, d);
    case Dimension::Force:
        return simple(kForce, text, d);
    case Dimension::Moment:
        return moment(text);
    case Dimension::Rotation:
        return simple(kRotation, text, d);
    case Dimension::Time:
        return simple(kTime, text, d);
    }
    return std::nullopt;
}

std::optional<Unit> parseDeformation(std::string_view text) {
    if (auto u = parse(text, Dimension::Length)) {
        return u;
    }
    return parse(text, Dimension::Rotation);
}

std::optional<Unit> parseForce(std::string_view text) {
    if (auto u = parse(text, Dimension::Force)) {
        return u;
    }
    return parse(text, Dimension::Moment);
}

const char* baseSymbol(Dimension d) {
    switch (d) {
    case Dimension::Length:
        return "m";
    case Dimension::Force:
        return "kN";
    case Dimension::Moment:
        return "kN m";
    case Dimension::Rotation:
        return "rad";
    case Dimension::Time:
        return "s";
    }
    return "";
}

std::string accepted(Dimension d) {
    switch (d) {
    case Dimension::Length:
        return list(kLength);
    case Dimension::Force:
        return list(kForce);
    case Dimension::Moment:
        return "a force unit times a length unit, e.g. kN m, N mm, kip in, lbf ft, tonf m";
    case Dimension::Rotation:
        return list(kRotation);
    case Dimension::Time:
        return list(kTime);
    }
    return "";
}

const char* dimensionName(Dimension d) {
    switch (d) {
    case Dimension::Length:
        return "length";
    case Dimension::Force:
        return "force";
    case Dimension::Moment:
        return "moment";
    case Dimension::Rotation:
        return "rotation";
    case Dimension::Time:
        return "time";
    }
    return "";
}

} // namespace hsmu::units
