// Issue 25 item 14: a specimen already loaded by a previous test ("2031 committed steps") was
// mentioned only inside the pre-flight's control description and Measured d showed 0. Against
// one real hsmu-controller process that keeps its specimen between console sessions:
//   1 a first test commits N steps (the rows the console received are the reference)
//   2 the next pre-flight shows an amber "Specimen loaded by an earlier test" item with N and
//     the last committed deformation (with its unit), Measured d shows that deformation, and
//     Start needs an explicit choice; "continue" is recorded and the specimen goes on from N
//   3 "fresh specimen" resets it at the controller (native Reset), the check is shown again
//     with a virgin specimen (no item, Measured d 0), and the controller's count restarts
//   4 a controller that refused a fresh specimen leaves only "continue" (the dialog alone)
// On the lab's 1280x720 screen (an offscreen screen of that size, see main()); no text of the
// new item is clipped, in en, es and zh_CN.

#include "comms/link/TcpControl.h"
#include "core/experiment/StepRecord.h"
#include "core/record/RecordReader.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/MainWindow.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/TestController.h"
#include "gui/app/Translations.h"
#include "tests/comms/ControllerProcess.h"

#include <QApplication>
#include <QCheckBox>
#include <QGroupBox>
#include <QLabel>
#include <QPointer>
#include <QPushButton>
#include <QRadioButton>
#include <QScreen>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace hsmu;
using namespace hsmu::gui;

namespace {

// The controller's own count, asked as any console would (a session of its own); nullopt
// while the controller still counts the last console's session (its bye is on the way: busy).
std::optional<PriorLoading> askController(quint16 port) {
    comms::TcpControl probe("127.0.0.1", port, "Spring", {}, comms::TcpControlOptions{});
    if (!probe.prepare(0.01).ok)
        return std::nullopt;
    return probe.priorLoading();
}

QString clipped(const QLabel* l) {
    if (l->text().isEmpty() || !l->isVisible())
        return {};
    if (l->wordWrap() ? l->height() + 1 < l->heightForWidth(l->width())
                      : l->width() + 1 < l->sizeHint().width())
        return QStringLiteral("'%1' (%2x%3)").arg(l->text()).arg(l->width()).arg(l->height());
    return {};
}

// The first driven test on the controller's specimen: every row the console received.
std::vector<StepRecord> firstTest(quint16 port, int minRows) {
    std::vector<StepRecord> rows;
    MainWindow window;
    window.setConfirmBeforeStart(false);
    window.setSpeed(4.0); // 400 steps/s: stopped long before its end
    window.show();
    window.setControllerAddress(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
    if (!window.loadConfiguration(QStringLiteral("sdof-bouc-wen")))
        return rows;
    TestController& c = window.controller();
    QObject::connect(&c, &TestController::recordsArrived, &window,
                     [&rows](const std::vector<StepRecord>& r) {
                         rows.insert(rows.end(), r.begin(), r.end());
                     });
    window.startTest();
    if (!QTest::qWaitFor([&] { return int(rows.size()) > minRows; }, 30000))
        return {};
    c.stop();
    if (!QTest::qWaitFor([&] { return c.state() == RunState::Stopped; }, 20000))
        return {};
    return rows;
}

} // namespace

class TestLoadedSpecimen : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    // A window on the controller, its pre-flight dialog open (nullptr on failure).
    PreflightDialog* openPreflight(MainWindow& window, quint16 port) {
        window.setSpeed(4.0);
        window.resize(1280, 720);
        window.show();
        if (!QTest::qWaitForWindowExposed(&window))
            return nullptr;
        window.setControllerAddress(QStringLiteral("tcp://127.0.0.1:%1").arg(port));
        if (!window.loadConfiguration(QStringLiteral("sdof-bouc-wen")))
            return nullptr;
        window.startTest();
        if (!QTest::qWaitFor([&] { return window.preflightDialog() != nullptr; }, 15000))
            return nullptr;
        if (!QTest::qWaitFor([&] { return window.preflightDialog()->isVisible(); }, 5000))
            return nullptr;
        return window.preflightDialog();
    }

    // A click as the operator makes it: the checks scroll, so the choice is brought into view.
    static void click(PreflightDialog* d, QAbstractButton* b) {
        d->findChild<QScrollArea*>(QStringLiteral("preflightScroll"))->ensureWidgetVisible(b);
        QCoreApplication::processEvents();
        // On the indicator: a radio button takes clicks on its circle and text only.
        QTest::mouseClick(b, Qt::LeftButton, {}, QPoint(8, b->height() / 2));
    }

    static QString measuredD(PreflightDialog* d) {
        auto* table = d->findChild<QTableWidget*>(QStringLiteral("preflightSpecimens"));
        return table && table->item(0, 4) ? table->item(0, 4)->text() : QString();
    }

    static QStringList notes(const QString& record) {
        QStringList out;
        const RecordData data = RecordReader(record.toStdString()).data(); // a copy: the reader goes
        for (const RecordNote& n : data.notes)
            out << QString::fromStdString(n.text);
        return out;
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(m_dir.isValid());
        ConsoleSettings::setRecordDirectory(QString());
        ConsoleSettings::setControllerAddress(QString());
        QCOMPARE(QGuiApplication::primaryScreen()->availableGeometry().size(), QSize(1280, 720));
    }
    void init() { Translations::install(*QCoreApplication::instance(), QStringLiteral("en")); }
    void cleanupTestCase() { init(); }

    void loadedSpecimenIsChosenExplicitly() {
        ControllerProcess lab({QStringLiteral("--config"), QStringLiteral("sdof-bouc-wen"),
                               QStringLiteral("--pace"), QStringLiteral("fast"),
                               QStringLiteral("--no-state-file")});
        QVERIFY2(lab.start(), qPrintable(lab.log()));

        // 1: a first test leaves N committed steps on the specimen.
        const std::vector<StepRecord> first = firstTest(lab.port(), 150);
        QVERIFY2(first.size() > 150, qPrintable(lab.log()));
        const StepRecord& last = first.back();
        const auto n = std::uint64_t(last.step);
        const double dLast = last.elements[0].commanded; // the target of the last commit [m]
        QVERIFY(std::isfinite(dLast) && std::abs(dLast) > 0.0);

        // 2: the next test's pre-flight shows it, amber, and asks.
        QTemporaryDir records;
        ConsoleSettings::setRecordDirectory(records.path());
        auto second = std::make_unique<MainWindow>();
        ConsoleSettings::setRecordDirectory(QString());
        PreflightDialog* d = openPreflight(*second, lab.port());
        QVERIFY2(d, qPrintable(lab.log()));
        auto* box = d->findChild<QGroupBox*>(QStringLiteral("loadedSpecimen"));
        QVERIFY2(box && box->isVisible(), "no pre-flight item for the loaded specimen");
        QVERIFY(box->styleSheet().contains(QStringLiteral("#fff3cd"))); // amber, as the checks
        const QString line =
            box->findChild<QLabel*>(QStringLiteral("loadedSpecimenLine"))->text();
        const QString dText = QString::number(dLast, 'g', 4) + QStringLiteral(" m");
        QVERIFY2(line.contains(QStringLiteral("%L1 committed steps").arg(qulonglong(n))) &&
                     line.contains(dText),
                 qPrintable(line + QStringLiteral(" / expected %1 steps, %2").arg(n).arg(dText)));
        QCOMPARE(measuredD(d), dText); // not "0 m"
        // Start waits for the choice, even with the zero offsets confirmed.
        d->zeroConfirmation()->setChecked(true);
        QVERIFY(!d->startButton()->isEnabled());
        QVERIFY(d->continueChoice() && d->freshChoice() && d->freshChoice()->isEnabled());
        QCOMPARE(d->specimenChoice(), PreflightDialog::SpecimenChoice::None);
        click(d, d->continueChoice());
        QCOMPARE(d->specimenChoice(), PreflightDialog::SpecimenChoice::Continue);
        QVERIFY(d->startButton()->isEnabled());
        QTest::mouseClick(d->startButton(), Qt::LeftButton);
        TestController& c2 = second->controller();
        QTRY_COMPARE_WITH_TIMEOUT(c2.state(), RunState::Running, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(c2.recordsDelivered() > 50, 20000);
        c2.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c2.state(), RunState::Stopped, 20000);
        const QString events =
            second->findChild<AlarmList*>()->rowsText(QLatin1Char('\t'), false);
        QVERIFY2(events.contains(QStringLiteral("the operator continues on it")), qPrintable(events));
        const QString record2 = c2.recordPath();
        second.reset(); // the record closed: read it whole
        const QString expectedOld = QStringLiteral("Spring: %1 committed steps, last deformation %2 m")
                                        .arg(n)
                                        .arg(QString::number(dLast, 'g', 6));
        const QStringList recorded = notes(record2);
        const QString recordedText =
            record2 + QStringLiteral(": ") + recorded.join(QLatin1Char('\n'));
        QVERIFY2(recorded.filter(QStringLiteral("action=loaded-specimen; old=") + expectedOld +
                                 QStringLiteral("; new=continue;"))
                         .size() == 1,
                 qPrintable(recordedText + QStringLiteral(" / expected ") + expectedOld));
        const int secondSteps = int(RecordReader(record2.toStdString()).data().steps.back());
        // The same specimen went on: its count is both tests'.
        std::optional<PriorLoading> asked;
        QTRY_VERIFY_WITH_TIMEOUT((asked = askController(lab.port())).has_value(), 10000);
        QCOMPARE(asked->committedSteps, n + std::uint64_t(secondSteps));

        // 3: a fresh specimen: reset at the controller, the check again, then a virgin start.
        ConsoleSettings::setRecordDirectory(records.path());
        auto third = std::make_unique<MainWindow>();
        ConsoleSettings::setRecordDirectory(QString());
        d = openPreflight(*third, lab.port());
        QVERIFY(d);
        QVERIFY(d->findChild<QGroupBox*>(QStringLiteral("loadedSpecimen")));
        QVERIFY(!d->startButton()->isEnabled());
        click(d, d->freshChoice());
        QVERIFY(d->startButton()->isEnabled()); // nothing starts from it: the reset, then again
        QCOMPARE(d->startButton()->text(), QStringLiteral("Reset the specimen"));
        QPointer<PreflightDialog> old(d);
        QTest::mouseClick(d->startButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(third->preflightDialog() && third->preflightDialog() != old &&
                                     third->preflightDialog()->isVisible(),
                                 15000);
        d = third->preflightDialog();
        QCOMPARE(third->controller().state(), RunState::Ready); // nothing armed meanwhile
        QVERIFY2(!d->findChild<QGroupBox*>(QStringLiteral("loadedSpecimen")),
                 "the reset specimen is still shown as loaded");
        QCOMPARE(measuredD(d), QStringLiteral("0 m"));
        // (asked by the console's own session: its pre-flight report after the reset)
        QCOMPARE(third->controller().preflight()->specimens.at(0).committedSteps, std::uint64_t(0));
        QVERIFY(!d->startButton()->isEnabled());
        d->zeroConfirmation()->setChecked(true);
        QTest::mouseClick(d->startButton(), Qt::LeftButton);
        TestController& c3 = third->controller();
        QTRY_COMPARE_WITH_TIMEOUT(c3.state(), RunState::Running, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(c3.recordsDelivered() > 50, 20000);
        c3.stop();
        QTRY_COMPARE_WITH_TIMEOUT(c3.state(), RunState::Stopped, 20000);
        const QString record3 = c3.recordPath();
        third.reset(); // the record closed: read it whole
        const QStringList recorded3 = notes(record3);
        const QString recordedText3 = recorded3.join(QLatin1Char('\n'));
        QVERIFY2(recorded3.filter(QStringLiteral("action=loaded-specimen; old=Spring: %1 committed "
                                                 "steps")
                                      .arg(n + std::uint64_t(secondSteps)))
                         .filter(QStringLiteral("; new=fresh;"))
                         .size() == 1,
                 qPrintable(recordedText3));
        const int thirdSteps = int(RecordReader(record3.toStdString()).data().steps.back());
        // The controller counts this test's steps only: a virgin specimen at its first step.
        asked.reset();
        QTRY_VERIFY_WITH_TIMEOUT((asked = askController(lab.port())).has_value(), 10000);
        QCOMPARE(asked->committedSteps, std::uint64_t(thirdSteps));
    }

    // 4: a controller that refused a fresh specimen (a rig: replaced by hand) leaves only
    // "continue"; the new item fits the 1280x720 screen in every language.
    void refusedFreshSpecimenLeavesContinue_data() {
        QTest::addColumn<QString>("language");
        QTest::newRow("en") << QStringLiteral("en");
        QTest::newRow("es") << QStringLiteral("es");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN");
    }
    void refusedFreshSpecimenLeavesContinue() {
        QFETCH(QString, language);
        QVERIFY(Translations::install(*QCoreApplication::instance(), language));
        PreflightReport report;
        report.integrator = "explicitNewmark";
        report.dt = 0.01;
        report.totalSteps = 1000;
        report.stability.stable = true;
        report.pga = 3.0;
        SpecimenPreflight s;
        s.element = "Bearing D";
        s.deformationUnit = "m";
        s.forceUnit = "kN";
        s.control = "TCP link tcp://127.0.0.1:5101 to specimen 'Bearing D'";
        s.committedSteps = 2031;
        s.lastDeformation = -0.0125;
        s.measuredDeformation = -0.0125;
        s.measuredForce = std::nan("");
        s.freshRefused = "controller at tcp://127.0.0.1:5101: not-supported: a rig's specimen";
        report.specimens.push_back(s);
        PreflightDialog d(report, {QStringLiteral("Changed since the last run: steps 900 -> 1000")});
        d.show();
        QVERIFY(QTest::qWaitForWindowExposed(&d));
        QVERIFY(d.findChild<QLabel*>(QStringLiteral("freshRefused")));
        QVERIFY(!d.freshChoice()->isEnabled());
        d.zeroConfirmation()->setChecked(true);
        QVERIFY(!d.startButton()->isEnabled());
        d.continueChoice()->setChecked(true);
        QVERIFY(d.startButton()->isEnabled());
        QCOMPARE(d.specimenChoice(), PreflightDialog::SpecimenChoice::Continue);
        QVERIFY(d.screen()->availableGeometry().contains(d.frameGeometry()));
        QStringList problems;
        for (const QLabel* l : d.findChildren<QLabel*>())
            if (const QString why = clipped(l); !why.isEmpty())
                problems << why;
        for (const QAbstractButton* b : d.findChildren<QRadioButton*>())
            if (b->width() + 1 < b->sizeHint().width())
                problems << b->text();
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QStringLiteral("; "))));
        // Measured d is the last deformation; F is not measured before the first step.
        auto* table = d.findChild<QTableWidget*>(QStringLiteral("preflightSpecimens"));
        QCOMPARE(table->item(0, 4)->text(), QStringLiteral("-0.0125 m"));
        QVERIFY(!table->item(0, 5)->text().contains(QStringLiteral("nan")));
    }

    // Continuing where the first target would jump past the increment limit (this test starts
    // from rest; seen in a real window: the controller's interlock held Bearing D at step 1,
    // |d - d_last| = 0.0204 > 0.02) is not offered: a fresh specimen is.
    void continueBeyondTheIncrementLimitIsNotOffered() {
        PreflightReport report;
        report.integrator = "explicitNewmark";
        report.dt = 0.005;
        report.totalSteps = 1200;
        report.stability.stable = true;
        report.pga = 3.0;
        SpecimenPreflight s;
        s.element = "Bearing D";
        s.deformationUnit = "m";
        s.forceUnit = "kN";
        s.limits.maxIncrement = 0.02;
        s.committedSteps = 1200;
        s.lastDeformation = 0.0204;
        s.measuredDeformation = s.lastDeformation;
        report.specimens.push_back(s);
        PreflightDialog d(report);
        QVERIFY(d.findChild<QLabel*>(QStringLiteral("continueExceedsIncrement")));
        QVERIFY(!d.continueChoice()->isEnabled());
        QVERIFY(d.freshChoice()->isEnabled());
        d.zeroConfirmation()->setChecked(true);
        QVERIFY(!d.startButton()->isEnabled());
        // Within the limit (0.0196 m back to rest) it is offered.
        report.specimens[0].lastDeformation = -0.0196;
        PreflightDialog within(report);
        QVERIFY(!within.findChild<QLabel*>(QStringLiteral("continueExceedsIncrement")));
        QVERIFY(within.continueChoice()->isEnabled());
    }
};

int main(int argc, char** argv) {
    // The lab's laptop: an offscreen screen of 1280x720 (Qt's offscreen platform reads the
    // screens from a JSON file).
    const std::string screens = (std::filesystem::temp_directory_path() /
                                 ("hsmu-screen-1280x720-" + std::to_string(getpid()) + ".json"))
                                    .string();
    std::ofstream(screens) << R"({"screens": [{"name": "laptop", "x": 0, "y": 0, "width": 1280,)"
                              R"( "height": 720, "logicalDpi": 96, "logicalBaseDpi": 96,)"
                              R"( "dpr": 1}]})";
    qputenv("QT_QPA_PLATFORM", QByteArray("offscreen:configfile=") + screens.c_str());
    int result = 0;
    {
        QApplication app(argc, argv);
        TestLoadedSpecimen test;
        QTEST_SET_MAIN_SOURCE_PATH
        result = QTest::qExec(&test, argc, argv);
    }
    std::remove(screens.c_str());
    return result;
}

#include "TestLoadedSpecimen.moc"
