#include "gui/app/Translations.h"

#include <QDir>
#include <QLocale>
#include <QTranslator>

namespace hsmu::gui {

namespace {
const QString kDir = QStringLiteral(":/i18n");
const QString kPrefix = QStringLiteral("hsmu_");
} // namespace

QStringList Translations::available() {
    QStringList codes;
    const QStringList files =
        QDir(kDir).entryList({kPrefix + QStringLiteral("*.qm")}, QDir::Files, QDir::Name);
    for (const QString& f : files)
        codes << f.mid(kPrefix.size(), f.size() - kPrefix.size() - 3);
    return codes;
}

QString Translations::displayName(const QString& code) {
    const QLocale locale(code);
    const QString name = locale.nativeLanguageName();
    if (name.isEmpty())
        return code;
    return code.contains(QLatin1Char('_'))
               ? QStringLiteral("%1 (%2)").arg(name, locale.nativeTerritoryName())
               : name;
}

bool Translations::install(QCoreApplication& app, const QString& code) {
    static QTranslator* current = nullptr; // the catalogue installed last
    if (current) {
        QCoreApplication::removeTranslator(current); // -> LanguageChange (English) if none follows
        delete current;
        current = nullptr;
    }
    auto* translator = new QTranslator(&app);
    const bool loaded = code.isEmpty() ? translator->load(QLocale(), QStringLiteral("hsmu"),
                                                          QStringLiteral("_"), kDir)
                                       : translator->load(kPrefix + code, kDir);
    if (!loaded) {
        delete translator;
        return false;
    }
    QCoreApplication::installTranslator(translator);
    current = translator;
    return true;
}

} // namespace hsmu::gui
