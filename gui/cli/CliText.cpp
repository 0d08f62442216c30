#include "gui/cli/CliText.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hsmu::gui {

namespace {
Translator g_translator = nullptr;
} // namespace

void setTranslator(Translator t) {
    g_translator = t;
}

std::string translate(const char* context, const char* source) {
    return g_translator ? g_translator(context, source) : std::string(source);
}

namespace {

/// Whether x lies exactly half-way between two values of `precision` decimals ('f') or
/// significant digits ('g'): its exact decimal expansion (a double's terminates) is a 5 then
/// zeros at the first dropped digit.
bool tie(double x, char format, int precision) {
    char buffer[1024];
    const int extra = 30;
    if (format == 'f')
        std::snprintf(buffer, sizeof buffer, "%.*f", precision + extra, x);
    else
        std::snprintf(buffer, sizeof buffer, "%.*e", std::max(precision, 1) - 1 + extra, x);
    std::string digits = buffer;
    if (format != 'f')
        digits = digits.substr(0, digits.find('e'));
    const std::string dropped = digits.substr(digits.size() - std::size_t(extra));
    return dropped.front() == '5' && dropped.find_first_not_of('0', 1) == std::string::npos;
}

} // namespace

std::string number(double x, char format, int precision) {
    if (std::isnan(x))
        return "nan";
    if (std::isinf(x))
        return x < 0 ? "-inf" : "inf";
    if (x == 0.0)
        x = 0.0; // Qt prints -0.0 as "0"
    // Qt rounds a tie away from zero, printf to even: the next double outward rounds as Qt.
    if (tie(x, format, precision))
        x = std::nextafter(x, x > 0 ? HUGE_VAL : -HUGE_VAL);
    char buffer[512];
    std::snprintf(buffer, sizeof buffer, format == 'f' ? "%.*f" : "%.*g", precision, x);
    return buffer;
}

namespace {

/// The placeholder at text[i] ("%N", N in 1..99, one or two digits): its number and length;
/// 0 if there is none.
int placeholder(const std::string& text, std::size_t i, std::size_t& length) {
    const auto digit = [&text](std::size_t k) {
        return k < text.size() && text[k] >= '0' && text[k] <= '9';
    };
    if (text[i] != '%' || !digit(i + 1))
        return 0;
    int n = text[i + 1] - '0';
    length = 2;
    if (digit(i + 2)) {
        n = n * 10 + (text[i + 2] - '0');
        length = 3;
    }
    return n;
}

} // namespace

Text& Text::args(const std::vector<std::string>& values) {
    // QString::arg(a, b, ...): the lowest placeholder number takes a, the next lowest b, ...,
    // in one pass (a value's own "%1" is not replaced again).
    std::vector<int> numbers;
    for (std::size_t i = 0, length = 0; i < m_text.size(); ++i)
        if (const int n = placeholder(m_text, i, length); n >= 1)
            numbers.push_back(n);
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
    if (numbers.size() > values.size())
        numbers.resize(values.size());
    if (numbers.empty())
        return *this; // no placeholder left: QString::arg warns and leaves the text
    std::string out;
    for (std::size_t i = 0; i < m_text.size(); ++i) {
        std::size_t length = 0;
        const int n = placeholder(m_text, i, length);
        const auto it = std::find(numbers.begin(), numbers.end(), n);
        if (n >= 1 && it != numbers.end()) {
            out += values[std::size_t(it - numbers.begin())];
            i += length - 1;
        } else {
            out += m_text[i];
        }
    }
    m_text = std::move(out);
    return *this;
}

Text& Text::arg(const std::string& value, int width) {
    std::string padded = value;
    if (width > 0 && padded.size() < std::size_t(width))
        padded.insert(0, std::size_t(width) - padded.size(), ' ');
    return args({padded});
}

Text& Text::arg(long long value, int width) {
    return arg(std::to_string(value), width);
}

} // namespace hsmu::gui
