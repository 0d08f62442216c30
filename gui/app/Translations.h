#pragma once
// Translations: the console's languages. Catalogues are compiled from translations/hsmu_*.ts
// and embedded under ":/i18n/hsmu_<code>.qm" (gui/CMakeLists.txt); English is the source
// language and needs none. install() loads the stored choice (ConsoleSettings::language(),
// "" = the system locale) before any window exists, and switches live later: the previous
// catalogue is removed, the new one installed, and Qt sends QEvent::LanguageChange to every
// widget, which retranslates itself (LiveText, changeEvent).
// Thread rules: main (GUI) thread.

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
    /// Install the catalogue for `code` ("" = the system locale) into app, replacing the one
    /// installed before. False if there is none for it (the English source strings are shown).
    static bool install(QCoreApplication& app, const QString& code);
};

} // namespace hsmu::gui
