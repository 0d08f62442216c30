#pragma once
// Translations: the console's languages. Catalogues are compiled from translations/hsmu_*.ts
// and embedded under ":/i18n/hsmu_<code>.qm" (gui/CMakeLists.txt); English is the source
// language and needs none. install() loads the stored choice (ConsoleSettings::language(),
// "" = the system locale) before any window exists; a change applies at the next start.
// Thread rules: main thread, before widgets are built.

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class Translations {
    Q_DECLARE_TR_FUNCTIONS(Translations)
public:
    /// Language codes with an embedded catalogue (e.g. "en", "zh_CN"), sorted.
    static QStringList available();
    /// The language's own name for a code, e.g. "English", "中文 (中国)".
    static QString displayName(const QString& code);
    /// Install the catalogue for `code` ("" = the system locale) into app. False if there is
    /// none for it (the English source strings are shown).
    static bool install(QCoreApplication& app, const QString& code);
};

} // namespace hsmu::gui
