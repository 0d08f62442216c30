#pragma once
// ReasonText: core's fixed English texts (a hold's reason, a safety limit's refusal, the
// stability verdicts, the inspector's alarms) written in one table, each under a stable,
// language-neutral code with numbered arguments %1, %2, ... core writes the English text
// from its code (reasonText), the record keeps that text; the console recognises it again
// (parseReason, also in a replayed record, where no arguments are stored) and shows its own
// translation of the code (gui/app/AlarmText). A text no template makes parses to nothing.
// Arguments are texts (numbers already formatted by the caller). Thread rules: none (pure).

#include <optional>
#include <string>
#include <vector>

namespace hsmu {

struct CodedText {
    std::string code;              ///< the template's code, e.g. "limit-target"
    std::vector<std::string> args; ///< its arguments, in order
};

/// The English text of `code` with `args` substituted for %1, %2, ...; "" for an unknown code.
std::string reasonText(const char* code, const std::vector<std::string>& args = {});

/// The code and arguments of a text made by reasonText (the whole text must match one
/// template; an argument is the shortest non-empty text that lets the rest match), or nothing.
std::optional<CodedText> parseReason(const std::string& english);

/// The number of arguments (the highest %n) of `code`'s template; -1 for an unknown code.
int reasonArgumentCount(const char* code);

/// Every code of the table, in its order (for tests: each must have a translation).
std::vector<std::string> reasonCodes();

} // namespace hsmu
