#pragma once
// CliText: the text of `hsmu run` without Qt, so that the Qt-free `hsmu` (gui/cli/FastRun.h)
// and the Qt Core front end (RunCommand) print the same bytes from one code path (RunFlow,
// RunReport):
//   translate(context, source): the installed translator's text (the Qt front ends install
//     QCoreApplication::translate, so the catalogues in translations/ keep applying); without
//     one, the English source;
//   Text::arg / args: QString::arg's rules (every occurrence of the lowest-numbered
//     placeholder %1..%99 replaced; a width right-aligns with spaces);
//   number(x, 'g' | 'f', precision): QString::number's forms ("nan", "inf", "-inf" as Qt).
// Thread rules: setTranslator() once at start, before any other thread; the rest is pure.

#include <string>
#include <vector>

namespace hsmu::gui {

using Translator = std::string (*)(const char* context, const char* source);

/// Install t (nullptr: English sources).
void setTranslator(Translator t);
/// source in the user's language (see above). Call it with string literals, as
/// translate("RunReport", "..."): lupdate reads such calls as QCoreApplication::translate.
std::string translate(const char* context, const char* source);

/// QString::number(x, format, precision): format 'g' (significant digits) or 'f' (decimals).
std::string number(double x, char format = 'g', int precision = 6);

class Text {
public:
    explicit Text(std::string text) : m_text(std::move(text)) {}
    /// QString::arg(a, b, ...): in one pass, the lowest placeholder number takes a, the next
    /// lowest b, ...
    Text& args(const std::vector<std::string>& values);
    /// QString::arg(value, width): width > 0 pads on the left with spaces.
    Text& arg(const std::string& value, int width = 0);
    Text& arg(long long value, int width = 0);
    Text& arg(int value, int width = 0) { return arg(static_cast<long long>(value), width); }
    Text& arg(std::size_t value) { return arg(std::to_string(value)); }
    const std::string& str() const { return m_text; }
    operator const std::string&() const { return m_text; }

private:
    std::string m_text;
};

} // namespace hsmu::gui
