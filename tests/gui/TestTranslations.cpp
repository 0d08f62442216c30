// The translation catalogues are complete and current: lupdate run over today's gui/ sources
// into a copy of each catalogue leaves no unfinished, vanished or empty entry, every
// placeholder (%1, %2, ...) of a source string survives in its translation, and the compiled
// catalogue embedded in the program answers with the catalogue's text.
// core's fixed texts (core/util/ReasonText) are user-visible too: every template code has a
// Spanish and a Chinese text that is not the English one, and the texts core's producers
// really write (a reader's error, a control's description, a link fault, an identifier's
// message) come out translated, so a new core text without a catalogue entry fails here.
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

#include "core/experimental/VirtualSpecimen.h"
#include "core/groundmotion/GroundMotionError.h"
#include "core/groundmotion/GroundMotionReader.h"
#include "core/hysteresis/LawFactory.h"
#include "core/record/RecordReader.h"
#include "core/util/ReasonText.h"
#include "gui/app/AlarmText.h"
#include "gui/app/MainWindow.h"
#include "gui/app/Translations.h"

#include <fstream>

namespace {

struct Message {
    QString context;
    QString source;
    QStringList translations; ///< one per numerus form, or one
    QString type;             ///< "", "unfinished", "vanished", "obsolete"
};

/// Reads the body of a <translation> element: its text, or its <numerusform> children.
void readTranslation(QXmlStreamReader& xml, Message& message) {
    QString text;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isCharacters())
            text += xml.text();
        else if (xml.isStartElement() && xml.name() == QLatin1String("numerusform"))
            message.translations << xml.readElementText();
        else if (xml.isEndElement() && xml.name() == QLatin1String("translation"))
            break;
    }
    if (message.translations.isEmpty())
        message.translations << text;
}

QList<Message> readCatalogue(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QList<Message> messages;
    QXmlStreamReader xml(&file);
    QString context;
    Message current;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name"))
            context = xml.readElementText();
        else if (name == QLatin1String("message"))
            current = Message{context, {}, {}, {}};
        else if (name == QLatin1String("source"))
            current.source = xml.readElementText();
        else if (name == QLatin1String("translation")) {
            current.type = xml.attributes().value(QLatin1String("type")).toString();
            readTranslation(xml, current);
            messages << current;
        }
    }
    return messages;
}

QSet<QString> placeholders(const QString& text) {
    static const QRegularExpression re(QStringLiteral("%L?\\d+|%n"));
    QSet<QString> found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured().remove(QLatin1Char('L')));
    return found;
}

QStringList catalogues() {
    const QDir dir(QStringLiteral(HSMU_SOURCE_DIR "/translations"));
    QStringList paths;
    for (const QString& name : dir.entryList({QStringLiteral("hsmu_*.ts")}, QDir::Files))
        paths << dir.filePath(name);
    return paths;
}

// User-visible texts given as a literal instead of through tr(): a call that shows text
// (setText, setToolTip, a message box, ...) whose argument starts with a string literal of
// letters. Each hit as "file:line: code".
QStringList literalUiTexts(const QString& source, const QString& name) {
    // The literal as the text argument: the first one of a setter, any one of a message box.
    static const char* const kSetter =
        R"re(\b(setText|setToolTip|setStatusTip|setWhatsThis|setWindowTitle|setPlaceholderText|)re"
        R"re(setSuffix|setPrefix|showMessage|addMessage|addItem|setItemText|setHeaderLabels?|)re"
        R"re(setTabText|setLabel|setName|setTitle)\s*\(\s*)re";
    static const char* const kMessageBox =
        R"re(QMessageBox(::|\s*\(\s*QMessageBox::)\w+\s*[(,][^;]*,\s*)re";
    static const char* const kLiteral =
        R"re((QStringLiteral\(|QLatin1String\(|QString::fromLatin1\(|QString::fromUtf8\(|)re"
        R"re(\{\s*)?"[A-Za-z][A-Za-z ]{2,})re";
    static const QRegularExpression call(QStringLiteral("(%1|%2)%3")
                                             .arg(QString::fromLatin1(kSetter),
                                                  QString::fromLatin1(kMessageBox),
                                                  QString::fromLatin1(kLiteral)));
    QStringList hits;
    const QStringList lines = source.split(QLatin1Char('\n'));
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString line = lines[i];
        if (line.trimmed().startsWith(QLatin1String("//")) ||
            line.contains(QLatin1String("hsmu-ui-literal-ok")))
            continue;
        if (call.match(line).hasMatch())
            hits << QStringLiteral("%1:%2: %3").arg(name).arg(i + 1).arg(line.trimmed());
    }
    return hits;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void atLeastTwoTranslationsBesideEnglish() {
        const QStringList paths = catalogues();
        QVERIFY2(paths.size() >= 3, qPrintable(paths.join(QLatin1Char(' '))));
        QVERIFY(paths.contains(QStringLiteral(HSMU_SOURCE_DIR "/translations/hsmu_en.ts")));
    }

    void cataloguesAreCompleteForTodaysSources_data() {
        QTest::addColumn<QString>("path");
        for (const QString& path : catalogues())
            QTest::newRow(qPrintable(QFileInfo(path).fileName())) << path;
    }
    void cataloguesAreCompleteForTodaysSources() {
        QFETCH(QString, path);
        QTemporaryDir tmp;
        QVERIFY(tmp.isValid());
        const QString copy = tmp.filePath(QFileInfo(path).fileName());
        QVERIFY(QFile::copy(path, copy));
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        QProcess lupdate;
        lupdate.start(QStringLiteral(HSMU_LUPDATE),
                      {QStringLiteral("-silent"), QStringLiteral("-no-obsolete"),
                       QStringLiteral("-locations"), QStringLiteral("none"),
                       QStringLiteral("-I"), QStringLiteral(HSMU_SOURCE_DIR),
                       QStringLiteral(HSMU_SOURCE_DIR "/gui"), QStringLiteral("-ts"), copy});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);

        const QList<Message> messages = readCatalogue(copy);
        QVERIFY2(messages.size() > 100, qPrintable(QString::number(messages.size())));
        QStringList problems;
        for (const Message& m : messages) {
            const QString where = m.context + QStringLiteral(": \"") + m.source.left(60) +
                                  QLatin1Char('"');
            if (!m.type.isEmpty()) {
                problems << m.type + QStringLiteral(" ") + where;
                continue;
            }
            for (const QString& t : m.translations) {
                if (t.trimmed().isEmpty())
                    problems << QStringLiteral("empty ") + where;
                else if (placeholders(t) != placeholders(m.source))
                    problems << QStringLiteral("placeholders differ ") + where;
            }
        }
        QVERIFY2(problems.isEmpty(),
                 qPrintable(QString::number(problems.size()) + QStringLiteral(" problem(s):\n") +
                            problems.mid(0, 20).join(QLatin1Char('\n'))));
    }

    void embeddedCatalogueAnswersWithItsText_data() { cataloguesAreCompleteForTodaysSources_data(); }
    void embeddedCatalogueAnswersWithItsText() {
        QFETCH(QString, path);
        const QString base = QFileInfo(path).completeBaseName();
        QTranslator translator;
        QVERIFY2(translator.load(base, QStringLiteral(":/i18n")), qPrintable(base));
        int checked = 0;
        for (const Message& m : readCatalogue(path)) {
            if (m.translations.size() != 1 || m.translations.front().isEmpty())
                continue;
            QCOMPARE(translator.translate(m.context.toUtf8().constData(),
                                          m.source.toUtf8().constData()),
                     m.translations.front());
            ++checked;
        }
        QVERIFY(checked > 100);
    }

    void everyCoreTextIsTranslated_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("es") << QStringLiteral("es");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void everyCoreTextIsTranslated() {
        QFETCH(QString, language);
        QVERIFY(hsmu::gui::Translations::install(*QCoreApplication::instance(), language));
        QStringList untranslated;
        for (const std::string& code : hsmu::reasonCodes()) {
            const int n = hsmu::reasonArgumentCount(code.c_str());
            QVERIFY2(n >= 0, code.c_str());
            std::vector<std::string> args;
            QStringList qargs;
            for (int i = 0; i < n; ++i) {
                qargs << QStringLiteral("Q%1x").arg(i + 1); // unlike any template's text
                args.push_back(qargs.back().toStdString());
            }
            const QString english = QString::fromStdString(hsmu::reasonText(code.c_str(), args));
            const QString shown = hsmu::gui::AlarmText::translate(code, qargs);
            if (shown.isNull() || shown == english)
                untranslated << QString::fromStdString(code) + QStringLiteral(": ") + english;
            for (const QString& a : qargs) // every argument is shown
                QVERIFY2(shown.contains(a), qPrintable(QString::fromStdString(code) + shown));
        }
        hsmu::gui::Translations::install(*QCoreApplication::instance(), QStringLiteral("en"));
        QVERIFY2(untranslated.isEmpty(),
                 qPrintable(language + QStringLiteral(": no translation of ") +
                            untranslated.join(QStringLiteral("\n"))));
    }

    // The texts core's producers write, as the console shows them in Spanish: translated
    // (the English template's words are gone), and the English again in English.
    void producersTextsAreTranslated() {
        QTemporaryDir dir;
        QStringList texts;
        const auto readerError = [&](const QString& name, const char* content) {
            const QString path = dir.filePath(name);
            if (content) {
                std::ofstream(path.toStdString()) << content;
            }
            try {
                hsmu::readGroundMotion(path.toStdString());
            } catch (const std::exception& e) {
                texts << QString::fromStdString(e.what());
                return;
            }
            QFAIL("the reader accepted a bad file");
        };
        readerError(QStringLiteral("missing.txt"), nullptr);
        readerError(QStringLiteral("single.txt"), "0.1\n0.2\n0.3\n");
        readerError(QStringLiteral("letters.txt"), "0 0.1\n0.01 abc\n");
        hsmu::VirtualSpecimenOptions options;
        options.forceNoiseStd = 0.01;
        options.actuator.type = hsmu::ActuatorModel::Type::Lag;
        texts << QString::fromStdString(
            hsmu::VirtualSpecimen(hsmu::makeLaw("boucWen", {}), options).description());
        const auto recordError = [&](const QString& name, const char* content) {
            const QString path = dir.filePath(name);
            if (content)
                std::ofstream(path.toStdString()) << content;
            try {
                hsmu::RecordReader reader(path.toStdString());
            } catch (const std::exception& e) {
                texts << QString::fromStdString(e.what());
                return;
            }
            QFAIL("the record reader accepted a bad file");
        };
        recordError(QStringLiteral("missing.h5"), nullptr);
        recordError(QStringLiteral("text.h5"), "not HDF5\n");
        QVERIFY(hsmu::gui::Translations::install(*QCoreApplication::instance(), QStringLiteral("es")));
        for (const QString& english : texts) {
            const QString shown = hsmu::gui::AlarmText::reason(english);
            QVERIFY2(shown != english, qPrintable(QStringLiteral("untranslated: ") + english));
            for (const char* word : {"cannot open", "cannot be opened", "does not exist",
                                     "single column", "expected a number", "not an HSMU record",
                                     "virtual specimen", "actuator"})
                QVERIFY2(!shown.contains(QLatin1String(word)),
                         qPrintable(english + QStringLiteral(" -> ") + shown));
        }
        QVERIFY(hsmu::gui::Translations::install(*QCoreApplication::instance(), QStringLiteral("en")));
        for (const QString& english : texts)
            QCOMPARE(hsmu::gui::AlarmText::reason(english), english);
    }

    // No user-visible text of the console bypasses the catalogues: every call that shows a
    // text takes it from tr() (or data), never from an English literal (the scanner is first
    // shown to catch one).
    void noUserVisibleLiteralOutsideTr() {
        QCOMPARE(literalUiTexts(QStringLiteral("label->setText(QStringLiteral(\"Hello world\"));"),
                                QStringLiteral("x.cpp"))
                     .size(),
                 1);
        QCOMPARE(literalUiTexts(QStringLiteral("QMessageBox::critical(this, tr(\"a\"), "
                                               "QStringLiteral(\"Cannot open\"));"),
                                QStringLiteral("x.cpp"))
                     .size(),
                 1);
        QVERIFY(literalUiTexts(QStringLiteral("label->setText(tr(\"Hello world\"));"),
                               QStringLiteral("x.cpp"))
                    .isEmpty());
        QStringList hits;
        int files = 0;
        QDirIterator it(QStringLiteral(HSMU_SOURCE_DIR "/gui"), {QStringLiteral("*.cpp")},
                        QDir::Files, QDirIterator::Subdirectories);
        while (it.hasNext()) {
            QFile f(it.next());
            QVERIFY(f.open(QIODevice::ReadOnly));
            hits << literalUiTexts(QString::fromUtf8(f.readAll()), it.fileName());
            ++files;
        }
        QVERIFY(files > 50);
        QVERIFY2(hits.isEmpty(), qPrintable(hits.join(QLatin1Char('\n'))));
    }

    // tr() in a QObject looks up the class's full name (hsmu::gui::MainWindow): lupdate must
    // have filed the window's strings under that context, or no translation ever shows.
    void windowStringsAreFiledUnderTheRuntimeContext_data() {
        cataloguesAreCompleteForTodaysSources_data();
    }
    void windowStringsAreFiledUnderTheRuntimeContext() {
        QFETCH(QString, path);
        const QString context =
            QString::fromLatin1(hsmu::gui::MainWindow::staticMetaObject.className());
        QTranslator translator;
        QVERIFY(translator.load(QFileInfo(path).completeBaseName(), QStringLiteral(":/i18n")));
        QVERIFY(QCoreApplication::installTranslator(&translator));
        int found = 0;
        for (const Message& m : readCatalogue(path)) {
            if (m.context != context || m.translations.size() != 1)
                continue;
            QCOMPARE(hsmu::gui::MainWindow::tr(m.source.toUtf8().constData()),
                     m.translations.front());
            ++found;
        }
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(found > 0, qPrintable(context));
    }
};

QTEST_MAIN(TestTranslations)
#include "TestTranslations.moc"
