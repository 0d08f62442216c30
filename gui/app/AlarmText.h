#pragma once
// AlarmText: the operator's language for core's alarm messages. core sends each message in
// English and, when it is made from a fixed template, the template's stable code and its
// arguments (Alarm::code, Alarm::args); this maps the code to a tr() text with the same
// arguments. core's other fixed texts (limits, hold reasons, stability: core/util/ReasonText)
// are recognised from their English text (also in a replayed record) and translated the
// same way. Unknown texts show the English text. The record keeps the code and the English
// text (docs/recording.md), never the translation.
// Also the pre-flight's stability verdict, made from StabilityReport's numbers.
// Thread rules: GUI thread (translations are installed there).

#include <QCoreApplication>
#include <QStringList>

#include <string>

namespace hsmu {
struct StabilityReport;
}

namespace hsmu::gui {

class AlarmText {
    Q_DECLARE_TR_FUNCTIONS(AlarmText)
public:
    /// The message for `code` with `args` in the current language; `english` if unknown.
    static QString describe(const std::string& code, const QStringList& args,
                            const QString& english);
    /// Any of core's fixed English texts (core/util/ReasonText: a hold reason, a limit's
    /// refusal, a stability verdict, an alarm, also "<element>: <reason>"), translated;
    /// the English text when no template makes it.
    static QString reason(const QString& english);
    /// The translation of core's template `code` with `args`; a null QString if unknown (or
    /// a wrong argument count).
    static QString translate(const std::string& code, const QStringList& args);
    /// The translation of one of the fixed words core writes into a description ("lag",
    /// "real-time", ...); other texts unchanged.
    static QString word(const QString& english);
    /// The stability check's sentence for the integrator `integrator` at time step dt [s].
    static QString stability(const StabilityReport& report, const QString& integrator,
                             double dt);
};

} // namespace hsmu::gui
