#include "gui/app/MainWindow.h"

#include "gui/PresetLibrary.h"
#include "gui/app/AlarmList.h"
#include "gui/app/AlarmText.h"
#include "gui/app/AlarmPanel.h"
#include "gui/app/DockFit.h"
#include "gui/app/RthsPanel.h"
#include "gui/app/AttentionBanner.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/EndConfirmation.h"
#include "gui/app/GroundMotionCheck.h"
#include "gui/app/LiveText.h"
#include "gui/app/ParametersPanel.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/PreflightChecks.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/SettingsDialog.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/TestStatusBar.h"
#include "gui/app/TestWorker.h"
#include "gui/app/WheelGuard.h"
#include "gui/plots/LivePlotsPanel.h"
#include "core/util/ReasonText.h"

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileDialog>
#include <QGuiApplication>
#include <QFile>
#include <QFileInfo>
#include <QDir>
#include <QMessageBox>
#include <QScreen>
#include <QScrollArea>
#include <QShowEvent>
#include <QTimer>
#include <QVBoxLayout>

#include <algorithm>
#include <stdexcept>

namespace hsmu::gui {

namespace {
bool active(RunState s) {
    return s == RunState::Running || s == RunState::Paused || s == RunState::Holding;
}
} // namespace

MainWindow::MainWindow(const ConfigOverrides& overrides, QWidget* parent)
    : QMainWindow(parent), m_overrides(overrides) {
    m_controller = new TestController(this);
    m_controller->setRecordDirectory(ConsoleSettings::recordDirectory());
    m_controls = new ControlBar(this);
    addToolBar(Qt::TopToolBarArea, m_controls);
    addAction(m_controls->emergencyHoldAction()); // shortcut alive even if the bar is hidden
    addActions(m_controls->runActions());         // F5, F6, F7, F10, Shift+F5 too

    // Centre: the attention banner over the plot area.
    auto* centre = new QWidget(this);
    auto* cv = new QVBoxLayout(centre);
    cv->setContentsMargins(0, 0, 0, 0);
    cv->setSpacing(0);
    m_banner = new AttentionBanner(centre);
    m_plots = new LivePlotsPanel(centre);
    cv->addWidget(m_banner);
    cv->addWidget(m_plots, 1);
    setCentralWidget(centre);

    m_setup = new SetupPanel(this);
    auto* setupScroll = new QScrollArea(this);
    setupScroll->setWidget(m_setup);
    setupScroll->setWidgetResizable(true);
    setupScroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    m_setupDock = addDock(setupScroll, QString(), QStringLiteral("setupDock"),
                          Qt::RightDockWidgetArea);
    m_parameters = new ParametersPanel(this);
    m_parametersDock = addDock(m_parameters, QString(), QStringLiteral("parametersDock"),
                               Qt::RightDockWidgetArea);
    m_pending = new PendingUpdatesPanel(this);
    QDockWidget* pending = addDock(m_pending, QString(), QStringLiteral("pendingDock"),
                                   Qt::RightDockWidgetArea);
    // The setup matters before a start, the parameters during a run: one tab each, the
    // plots keep the width; the pending updates stay in view below.
    splitDockWidget(m_setupDock, pending, Qt::Vertical);
    tabifyDockWidget(m_setupDock, m_parametersDock);
    m_setupDock->raise();

    auto* alarmPanel = new AlarmPanel(this);
    m_alarms = alarmPanel->list();
    m_alarmDock = addDock(alarmPanel, QString(), QStringLiteral("alarmDock"),
                          Qt::BottomDockWidgetArea);
    connect(m_banner, &AttentionBanner::acknowledgeAllRequested, m_alarms,
            &AlarmList::acknowledgeAll);
    connect(m_alarms, &AlarmList::attentionChanged, this, &MainWindow::onAttention);
    // Real-time hybrid simulation: its own view (hidden until the View menu shows it); the
    // emergency hold (every window, always) holds its loop too.
    // In a scroll area: opening the dock never grows the window past its 1280x720 design size.
    m_rths = new RthsPanel(m_alarms, this);
    auto* rthsScroll = new QScrollArea(this);
    rthsScroll->setWidget(m_rths);
    rthsScroll->setWidgetResizable(true);
    m_rthsDock = addDock(rthsScroll, QString(), QStringLiteral("rthsDock"), Qt::LeftDockWidgetArea);
    m_rthsDock->hide();
    // Shown, it takes its form's width (the hybrid test's plots beside it are idle then).
    fitDockToForm(*this, *m_rthsDock, *rthsScroll);
    connect(m_controls->emergencyHoldAction(), &QAction::triggered, m_rths, &RthsPanel::emergencyHold);

    m_status = new TestStatusBar(this);
    setStatusBar(m_status);
    buildMenus();
    wireController();

    resize(1500, 920);
    resizeDocks({m_alarmDock}, {200}, Qt::Vertical); // 5+ rows at 1280x720
    resizeDocks({m_setupDock}, {440}, Qt::Horizontal);
    resizeDocks({m_setupDock, pending}, {440, 340}, Qt::Vertical); // the list ~110 px at 720
    m_setup->setControllerAddress(ConsoleSettings::controllerAddress());
    if (const QByteArray g = ConsoleSettings::windowGeometry(); !g.isEmpty())
        restoreGeometry(g);
    if (const QByteArray s = ConsoleSettings::windowState(); !s.isEmpty())
        restoreState(s);
    fitToScreen(); // the designed or remembered size, never beyond the screen
    WheelGuard::install(); // no value changes by scrolling over a field (every window)
    // Live language switching (Translations::install): every piece retranslates itself on
    // QEvent::LanguageChange (LiveText, changeEvent); here the window's own texts.
    LiveText::bind(this, [this, pending] {
        m_setupDock->setWindowTitle(tr("Test setup"));
        m_parametersDock->setWindowTitle(tr("Parameters"));
        pending->setWindowTitle(tr("Pending updates"));
        m_alarmDock->setWindowTitle(tr("Alarms and events"));
        m_rthsDock->setWindowTitle(tr("Real-time hybrid simulation"));
        showTitle();
        if (m_controller->hasTest())
            showLink();
        // Plot titles are set when a test is configured: again now if no data would be lost.
        if (m_controller->hasTest() && !active(m_controller->state()) &&
            m_controller->state() != RunState::Finished &&
            m_controller->state() != RunState::Stopped)
            m_plots->configure(m_controller->layout(), m_controller->config());
    });
}

void MainWindow::showTitle() {
    if (m_controller->hasTest())
        setWindowTitle(
            tr("HSMU Console - %1").arg(QString::fromStdString(m_controller->config().name)));
    else
        setWindowTitle(tr("HSMU Console"));
}

MainWindow::~MainWindow() = default;

void MainWindow::fitToScreen() {
    const QScreen* s = screen() ? screen() : QGuiApplication::primaryScreen();
    if (!s)
        return;
    const QRect available = s->availableGeometry();
    // The window system's frame (title bar, borders) once shown; before, a usual one.
    QMargins frame(frameGeometry().left() - geometry().left(),
                   geometry().top() - frameGeometry().top(),
                   frameGeometry().right() - geometry().right(),
                   frameGeometry().bottom() - geometry().bottom());
    if (!isVisible() || frame.isNull())
        frame = QMargins(4, 32, 4, 4);
    const QSize room = available.size().shrunkBy(frame).expandedTo(QSize(320, 240));
    if (isMaximized() || isFullScreen())
        return; // the window system keeps it on the screen
    const QSize size = this->size().boundedTo(room);
    if (size != this->size())
        resize(size);
    m_fittedSize = size;
    const QSize outer = size.grownBy(frame);
    const QPoint at = frameGeometry().topLeft();
    const QPoint inside(
        std::clamp(at.x(), available.left(), std::max(available.left(), available.right() + 1 - outer.width())),
        std::clamp(at.y(), available.top(), std::max(available.top(), available.bottom() + 1 - outer.height())));
    if (inside != at)
        move(inside);
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (!m_fittedOnShow) { // again with the real frame, once the window system placed it
        m_fittedOnShow = true;
        QTimer::singleShot(0, this, [this] {
            if (size() == m_fittedSize) // not a size someone chose since (resize, -geometry)
                fitToScreen();
        });
    }
}

QDockWidget* MainWindow::addDock(QWidget* panel, const QString& title, const QString& name,
                                 Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name); // saveState / restoreState key
    dock->setWidget(panel);
    addDockWidget(area, dock);
    return dock;
}

bool MainWindow::loadConfiguration(const QString& nameOrPath, QString* error) {
    try {
        TestConfig cfg = PresetLibrary::load(nameOrPath);
        m_overrides.applyTo(cfg);
        if (nameOrPath != m_source)
            m_policyChoice.reset(); // another test: its own policy
        applyPolicyChoice(cfg);
        m_setup->setConfig(cfg);
        QString why;
        const auto address = m_setup->controller(&why);
        if (!address)
            throw std::runtime_error(why.toStdString());
        m_controller->setLinkToken(m_setup->token());
        m_controller->load(cfg, *address);
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        m_alarms->addMessage(
            [nameOrPath, message] {
                return tr("cannot load %1: %2").arg(nameOrPath, AlarmText::reason(message));
            },
            AlarmSeverity::Critical);
        m_status->showMessage(AlarmText::reason(message), 10000);
        m_controls->setRunState(m_controller->state());
        m_status->setRunState(m_controller->state());
        if (error)
            *error = message;
        return false;
    }
    m_source = nameOrPath;
    ConsoleSettings::setControllerAddress(m_setup->controllerText());
    const bool preset =
        !PresetLibrary::resourcePath(nameOrPath).isEmpty() && !QFileInfo::exists(nameOrPath);
    m_controls->selectPreset(preset ? nameOrPath : QString());
    if (!preset)
        ConsoleSettings::addRecentFile(nameOrPath);
    return true;
}

bool MainWindow::applySetup() {
    QString error;
    const auto cfg = m_setup->edited(&error);
    const auto address = cfg ? m_setup->controller(&error) : std::nullopt;
    if (!cfg || !address) {
        m_alarms->addMessage(
            [error] { return tr("setup not applied: %1").arg(AlarmText::reason(error)); },
            AlarmSeverity::Warning);
        m_status->showMessage(error, 10000);
        return false;
    }
    try {
        TestConfig withPolicy = *cfg;
        applyPolicyChoice(withPolicy);
        m_controller->setLinkToken(m_setup->token());
        m_controller->load(withPolicy, *address);
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        m_alarms->addMessage(
            [message] { return tr("setup not applied: %1").arg(AlarmText::reason(message)); },
            AlarmSeverity::Critical);
        m_status->showMessage(AlarmText::reason(message), 10000);
        return false;
    }
    ConsoleSettings::setControllerAddress(m_setup->controllerText());
    m_setup->markApplied();
    return true;
}

void MainWindow::testLink() {
    const RunState s = m_controller->state();
    if (active(s))
        return;
    if ((m_setup->isDirty() || s != RunState::Ready) && !applySetup())
        return;
    m_status->showMessage(tr("testing the link..."), 5000);
    m_controller->prepare(); // connects; -> preflightReady (link shown connected) or Failed
}

void MainWindow::previewGroundMotion() {
    QString error;
    const auto cfg = m_setup->edited(&error);
    if (cfg) {
        QString file = QString::fromStdString(cfg->groundMotion.file);
        if (!file.isEmpty() && QFileInfo(file).isRelative() && !cfg->sourcePath.empty())
            file = QFileInfo(QString::fromStdString(cfg->sourcePath)).dir().filePath(file);
        error = GroundMotionCheck::binaryFileProblem(file);
    }
    if (cfg && error.isEmpty() && m_plots->showGroundMotionOf(*cfg, &error)) {
        m_setup->setGroundMotionStatus(QString());
        return;
    }
    QString status = tr("This ground motion cannot be used: %1").arg(AlarmText::reason(error));
    if (error.contains(QString::fromStdString(reasonText("single-column-needs-dt"))))
        status += QLatin1Char(' ') + tr("Enter the record's sample step below the file.");
    m_setup->setGroundMotionStatus(status);
    m_alarms->addMessage(
        [error] { return tr("ground motion not usable: %1").arg(AlarmText::reason(error)); },
        AlarmSeverity::Warning);
}

void MainWindow::onPolicyChosen(ReporterPolicy policy, int everyN) {
    m_policyChoice = std::make_pair(policy, everyN);
    const RunState s = m_controller->state();
    if (s == RunState::Ready || active(s)) // the loaded or running test takes it at once
        m_controller->setReporterPolicy(policy, everyN); // recorded by the worker as an event
    // Between runs it is the next run's: applyPolicyChoice() when Start reloads the test.
}

void MainWindow::applyPolicyChoice(TestConfig& cfg) const {
    if (!m_policyChoice || !cfg.updating.enabled)
        return;
    cfg.updating.policy = m_policyChoice->first;
    cfg.updating.everyN = m_policyChoice->second;
}

void MainWindow::confirmEnd(const QString& objectName, const QString& question,
                            const QString& yes, std::function<void()> then) {
    if (m_confirmation)
        return;
    m_confirmation = EndConfirmation::open(this, objectName, question, yes,
                                           m_controls->emergencyHoldAction(),
                                           [this, then = std::move(then)](bool confirmed) {
                                               m_confirmation = nullptr;
                                               if (confirmed)
                                                   then();
                                           });
}

void MainWindow::requestStop() {
    if (!active(m_controller->state())) {
        m_controller->stop();
        return;
    }
    confirmEnd(QStringLiteral("stopConfirmation"),
               tr("End the test now? The specimen is held, the test cannot be resumed, and "
                  "every step so far stays in the record."),
               tr("End the test and keep the data"), [this] { m_controller->stop(); });
}

void MainWindow::setControllerAddress(const QString& address) {
    m_setup->setControllerAddress(address);
}

void MainWindow::setSpeed(double factor) {
    m_controls->setSpeed(factor);
    m_controller->setSpeed(factor); // exact, even if the selector has no such entry
}

void MainWindow::startTest() {
    requestRun(RunRequest::Start);
}

void MainWindow::singleStep() {
    if (m_controller->state() == RunState::Paused)
        m_controller->singleStep();
    else
        requestRun(RunRequest::SingleStep);
}

void MainWindow::requestRun(RunRequest request) {
    const RunState s = m_controller->state();
    if (m_setup->isDirty() && !active(s)) {
        if (!applySetup())
            return;
    } else if ((s == RunState::Finished || s == RunState::Stopped || s == RunState::Failed) &&
               !m_source.isEmpty()) {
        if (!applySetup())
            return;
    }
    if (m_controller->state() != RunState::Ready)
        return;
    if (!m_confirmBeforeStart) {
        m_controller->skipPreflight(); // recorded: no pre-flight dialog was shown
        request == RunRequest::Start ? m_controller->start() : m_controller->singleStep();
        return;
    }
    m_pendingRun = request;
    if (m_controller->preflight())
        showPreflight(*m_controller->preflight()); // prepared before, the dialog was cancelled
    else
        m_controller->prepare(); // -> preflightReady -> showPreflight
    m_status->showMessage(tr("preparing the test (pre-flight)..."), 5000);
}

void MainWindow::showPreflight(const PreflightReport& report) {
    m_status->link()->refresh(); // prepared: the monitor has every site's state
    m_status->clearMessage();     // "testing the link..." / "preparing..." is answered
    if (m_pendingRun == RunRequest::None && !m_preflight) { // Test link
        const QString where = QString::fromStdString(m_controller->controllerAddress().toString());
        m_alarms->addMessage(
            [where] {
                return tr("link tested: %1 answered; the test is prepared, Start shows the "
                          "pre-flight check")
                    .arg(where);
            },
            AlarmSeverity::Info);
        return;
    }
    if (m_pendingRun == RunRequest::None || m_preflight)
        return;
    const QVariantMap current = PreflightChecks::runSettingsOf(
        m_controller->config(), QString::fromStdString(m_controller->controllerAddress().toString()),
        report);
    const QString name = QString::fromStdString(m_controller->config().name);
    m_preflight = new PreflightDialog(
        report, PreflightChecks::warnings(report, current, ConsoleSettings::lastRun(name)), this);
    m_preflight->setAttribute(Qt::WA_DeleteOnClose);
    m_preflight->addAction(m_controls->emergencyHoldAction()); // alive over the modal dialog
    connect(m_preflight, &QDialog::finished, this, [this, current, name](int result) {
        const RunRequest request = m_pendingRun;
        const PreflightDialog::SpecimenChoice choice = m_preflight->specimenChoice();
        m_pendingRun = RunRequest::None;
        m_preflight = nullptr;
        if (result != QDialog::Accepted || request == RunRequest::None) {
            m_alarms->addMessage([] { return tr("start cancelled at the pre-flight check"); },
                                 AlarmSeverity::Info);
            return;
        }
        if (choice == PreflightDialog::SpecimenChoice::Fresh) {
            // Nothing starts: the controllers reset, the check comes again (preflightReady).
            m_pendingRun = request;
            m_controller->chooseLoadedSpecimens(true);
            m_status->showMessage(tr("asking the controller for a fresh specimen..."), 5000);
            return;
        }
        if (choice == PreflightDialog::SpecimenChoice::Continue)
            m_controller->chooseLoadedSpecimens(false); // an event per loaded specimen
        ConsoleSettings::setLastRun(name, current);
        m_controller->confirmPreflight(); // an event in the record and the list
        request == RunRequest::Start ? m_controller->start() : m_controller->singleStep();
    });
    m_preflight->open(); // window-modal, never a nested wait on the GUI thread
}

void MainWindow::openConfigurationFile() {
    const QString file =
        QFileDialog::getOpenFileName(this, tr("Open configuration"), QString(),
                                     tr("Test configurations (*.json);;All files (*)"));
    if (file.isEmpty())
        return;
    QString error;
    if (!loadConfiguration(file, &error))
        QMessageBox::critical(this, tr("Configuration error"), error);
}

void MainWindow::openSettings() {
    auto* dialog = new SettingsDialog(this);
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->addAction(m_controls->emergencyHoldAction());
    connect(dialog, &QDialog::accepted, this,
            [this] {
                m_controller->setRecordDirectory(ConsoleSettings::recordDirectory());
                m_rths->setRecordFolder(RthsPanel::defaultRecordFolder());
            });
    dialog->open();
}

void MainWindow::onTestLoaded() {
    m_plots->configure(m_controller->layout(), m_controller->config());
    m_alarms->clearAlarms();
    const QString name = QString::fromStdString(m_controller->config().name);
    const QString source = QString::fromStdString(m_controller->config().sourcePath);
    m_alarms->addMessage(
        [name, source] { return tr("loaded %1 (%2)").arg(AlarmText::reason(name), source); },
        AlarmSeverity::Info);
    showTitle();
    m_status->setProgress(0, 0, 0.0, 0.0);
    m_status->setRecordingFile(QString());
    m_parameters->setSnapshot({});
    m_pending->setSnapshot({});
    showLink();
    m_pendingRun = RunRequest::None;
    m_setupDock->raise();
}

void MainWindow::showLink() {
    const std::shared_ptr<const SiteMonitor> monitor = m_controller->siteMonitor();
    m_setup->setSiteMonitor(monitor);
    const TestConfig& cfg = m_controller->config();
    QList<SiteHealthLabel::Site> sites;
    for (const SiteSpec& s : cfg.sites)
        sites.push_back({QString::fromStdString(s.name), QString::fromStdString(s.address),
                         false, QString()});
    const bool unsited = std::any_of(cfg.elements.begin(), cfg.elements.end(),
                                     [](const ElementSpec& e) {
                                         return e.experimental && e.site.empty();
                                     });
    if (unsited || sites.isEmpty()) { // the site "controller": the controller of the setup
        const comms::LinkAddress& a = m_controller->controllerAddress();
        SiteHealthLabel::Site site{QString::fromLatin1(kDefaultSiteName),
                                   QString::fromStdString(a.toString()),
                                   a.kind == comms::LinkAddress::Kind::Builtin, QString()};
        if (a.kind == comms::LinkAddress::Kind::SimApp ||
            a.kind == comms::LinkAddress::Kind::GenericTcp) {
            // What the client sends in OpenFresco's sizes header (checked at connect).
            const LinkSpec& spec = cfg.link;
            const auto list = [](const std::array<int, 5>& v) {
                return QStringLiteral("%1 %2 %3 %4 %5")
                    .arg(v[0]).arg(v[1]).arg(v[2]).arg(v[3]).arg(v[4]);
            };
            site.detail = tr("(dataSize %1; ctrl sizes %2; daq sizes %3)")
                              .arg(spec.dataSize)
                              .arg(list(spec.ctrlSizes), list(spec.daqSizes));
        }
        sites.push_back(site);
    }
    m_status->setLink(sites, monitor);
}

void MainWindow::onStateChanged(RunState state, const QString& message) {
    m_controls->setRunState(state);
    m_status->setRunState(state);
    m_setup->setEditable(!active(state));
    const bool live = state == RunState::Ready || active(state);
    m_parameters->setEditable(live);
    m_pending->setEditable(live);
    // Between runs the policy is chosen for the next run (applied when Start reloads).
    m_pending->setNextRunPolicyEditable(state == RunState::Stopped ||
                                        state == RunState::Finished ||
                                        state == RunState::Failed);
    if (state == RunState::Running && !m_setupDock->isFloating())
        m_parametersDock->raise(); // the setup is read-only now
    if (state != RunState::Ready) {
        m_pendingRun = RunRequest::None;
        if (m_preflight)
            m_preflight->reject(); // e.g. held from the dialog: nothing may start from it
    }
    if (state == RunState::Finished) {
        const auto [step, time] = m_lastProgress;
        m_alarms->addMessage(
            time, step,
            [step, time] {
                return tr("test finished: %1 steps, t = %2 s").arg(step).arg(time, 0, 'f', 2);
            },
            AlarmSeverity::Info);
    }
    if (message.isEmpty() && (state == RunState::Running || state == RunState::Paused))
        m_status->clearMessage(); // a hold's reason is over once the test moves again
    if (!message.isEmpty()) {
        // A hold's or a failure's reason from core (English, language-neutral): translated
        // when it is one of core's fixed texts (core/util/ReasonText).
        const QString shown = AlarmText::reason(message);
        m_status->showMessage(shown, 15000);
        if (state == RunState::Failed)
            m_alarms->addMessage(
                [message] {
                    return tr("the test cannot start: %1").arg(AlarmText::reason(message));
                },
                AlarmSeverity::Critical);
    }
}

void MainWindow::onAlarm(const Alarm& alarm) {
    // The hold of the operator's own Stop needs no attention (no red banner).
    const bool ownStop = alarm.kind == AlarmKind::OperatorHold && !alarm.args.empty() &&
                         alarm.args.front() == TestWorker::kStopReason;
    m_alarms->addAlarm(alarm, ownStop);
    if (alarm.kind == AlarmKind::ControlFault)
        m_status->link()->refresh(); // the monitor has the fault already
}

void MainWindow::onAttention(int count, const QString& latest) {
    m_banner->setAttention(count, latest);
    if (count == 0)
        return;
    m_alarmDock->show();
    m_alarmDock->raise();
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (active(m_controller->state()) && !m_closeConfirmed) {
        event->ignore();
        confirmEnd(QStringLiteral("quitConfirmation"),
                   tr("A test is running. Quit the console? The test is ended first: the "
                      "specimen is held and every step so far stays in the record."),
                   tr("End the test, keep the data and quit"), [this] {
                       m_closeConfirmed = true;
                       m_controller->stop();
                       close();
                   });
        return;
    }
    ConsoleSettings::saveWindow(saveGeometry(), saveState());
    QMainWindow::closeEvent(event);
}

} // namespace hsmu::gui
