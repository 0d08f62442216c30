#include "gui/app/MainWindow.h"
// MainWindow's menus and signal wiring: which control reaches which TestController slot, and
// how the operator's events and the worker's reports come back to the panels.

#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/ControlBar.h"
#include "gui/app/LiveText.h"
#include "gui/app/OperatorEvent.h"
#include "gui/app/ParametersPanel.h"
#include "gui/app/PendingUpdatesPanel.h"
#include "gui/app/PreflightDialog.h"
#include "gui/app/SetupPanel.h"
#include "gui/app/TestController.h"
#include "gui/app/TestStatusBar.h"
#include "gui/app/TestWorker.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/replay/ReplayWindow.h"

#include "core/Version.h"

#include <QAction>
#include <QCoreApplication>
#include <QDesktopServices>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QUrl>

namespace hsmu::gui {

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(QString());
    // Ctrl+O belongs to the tool bar's action: one shortcut, one action.
    QAction* open = file->addAction(QString(), this, &MainWindow::openConfigurationFile);
    m_recentMenu = file->addMenu(QString());
    connect(m_recentMenu, &QMenu::aboutToShow, this, &MainWindow::rebuildRecentMenu);
    rebuildRecentMenu();
    file->addSeparator();
    QAction* record =
        file->addAction(QString(), this, [this] { ReplayWindow::openWithDialog(this); });
    file->addSeparator();
    QAction* note = file->addAction(QString(), this, &MainWindow::askForNote);
    note->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_N));
    file->addSeparator();
    QAction* settings = file->addAction(QString(), this, &MainWindow::openSettings);
    file->addSeparator();
    QAction* quit = file->addAction(QString(), this, &QWidget::close);
    quit->setShortcut(QKeySequence::Quit);
    m_viewMenu = menuBar()->addMenu(QString());
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        m_viewMenu->addAction(dock->toggleViewAction());
    QMenu* help = menuBar()->addMenu(QString());
    help->setObjectName(QStringLiteral("helpMenu"));
    QAction* guide = help->addAction(QString(), this, &MainWindow::openGuide);
    guide->setShortcut(QKeySequence::HelpContents);
    QAction* keys = help->addAction(QString(), this, &MainWindow::showShortcuts);
    keys->setObjectName(QStringLiteral("showShortcuts"));
    help->addSeparator();
    QAction* about = help->addAction(QString(), this, &MainWindow::showAbout);
    LiveText::bind(menuBar(), [=, this] {
        file->setTitle(tr("&File"));
        open->setText(tr("&Open configuration..."));
        m_recentMenu->setTitle(tr("Open &recent"));
        record->setText(tr("Open r&ecord..."));
        note->setText(tr("Add &note..."));
        note->setToolTip(tr("Record a note at the current step of the test"));
        settings->setText(tr("&Settings..."));
        quit->setText(tr("&Quit"));
        quit->setToolTip(tr("Quit the console (asks first while a test runs)"));
        m_viewMenu->setTitle(tr("&View"));
        help->setTitle(tr("&Help"));
        guide->setText(tr("Console &guide"));
        guide->setToolTip(tr("The console's documentation (docs/console.md)"));
        keys->setText(tr("&Keyboard shortcuts"));
        about->setText(tr("&About HSMU Console"));
    });
}

QString MainWindow::shortcutsText() {
    const auto key = [](const QKeySequence& k) { return k.toString(QKeySequence::NativeText); };
    const QStringList rows{
        tr("%1: Start (after the pre-flight check)").arg(key(QKeySequence(Qt::Key_F5))),
        tr("%1: Pause").arg(key(QKeySequence(Qt::Key_F6))),
        tr("%1: Resume").arg(key(QKeySequence(Qt::Key_F7))),
        tr("%1: Single step").arg(key(QKeySequence(Qt::Key_F10))),
        tr("%1: Stop (asks first)").arg(key(QKeySequence(Qt::SHIFT | Qt::Key_F5))),
        tr("%1: Emergency hold (every window, always)")
            .arg(key(ControlBar::emergencyHoldShortcut())),
        tr("%1: Add a note to the record").arg(key(QKeySequence(Qt::CTRL | Qt::Key_N))),
        tr("%1: Open a configuration").arg(key(QKeySequence::Open)),
        tr("%1: Copy the selected alarms and events").arg(key(QKeySequence::Copy)),
        tr("%1: Console guide").arg(key(QKeySequence::HelpContents)),
        tr("%1: Quit (asks first while a test runs)").arg(key(QKeySequence::Quit)),
    };
    return rows.join(QLatin1Char('\n'));
}

void MainWindow::showShortcuts() {
    QMessageBox::information(this, tr("Keyboard shortcuts"), shortcutsText());
}

void MainWindow::showAbout() {
    QMessageBox::about(
        this, tr("About HSMU Console"),
        tr("HSMU Console %1\nHybrid simulation with online model updating (Hashemi, Masroor & "
           "Mosqueda, EESD 2014).")
            .arg(QString::fromLatin1(hsmu::versionString())));
}

void MainWindow::openGuide() {
    // Installed: PREFIX/share/doc/hsmu; in a build tree: the source tree's docs.
    const QDir bin(QCoreApplication::applicationDirPath());
    for (const QString& candidate :
         {bin.filePath(QStringLiteral("../share/doc/hsmu/console.md")),
          bin.filePath(QStringLiteral("../../docs/console.md"))})
        if (QFileInfo::exists(candidate)) {
            QDesktopServices::openUrl(QUrl::fromLocalFile(QFileInfo(candidate).canonicalFilePath()));
            return;
        }
    QMessageBox::information(this, tr("Console guide"),
                             tr("The guide is docs/console.md of the source tree, installed as "
                                "share/doc/hsmu/console.md."));
}

void MainWindow::askForNote() {
    if (!m_controller->hasTest()) {
        QMessageBox::information(this, tr("Add note"), tr("Load and start a test first."));
        return;
    }
    bool ok = false;
    const QString text = QInputDialog::getMultiLineText(
        this, tr("Add note"), tr("Note (recorded with the current step and test time):"),
        QString(), &ok);
    if (ok && !text.trimmed().isEmpty())
        m_controller->addNote(text.trimmed());
}

void MainWindow::rebuildRecentMenu() {
    m_recentMenu->clear();
    const QStringList files = ConsoleSettings::recentFiles();
    for (const QString& f : files)
        m_recentMenu
            ->addAction(QFileInfo(f).fileName(), this,
                        [this, f] {
                            QString error;
                            if (!loadConfiguration(f, &error))
                                QMessageBox::critical(this, tr("Configuration error"), error);
                        })
            ->setToolTip(f);
    if (files.isEmpty())
        m_recentMenu->addAction(tr("(none)"))->setEnabled(false);
}

void MainWindow::wireController() {
    connect(m_controls, &ControlBar::presetChosen, this,
            [this](const QString& id) { loadConfiguration(id); });
    connect(m_controls, &ControlBar::openRequested, this, &MainWindow::openConfigurationFile);
    connect(m_controls, &ControlBar::startRequested, this, &MainWindow::startTest);
    connect(m_controls, &ControlBar::pauseRequested, m_controller, &TestController::pause);
    connect(m_controls, &ControlBar::singleStepRequested, this, &MainWindow::singleStep);
    connect(m_controls, &ControlBar::resumeRequested, m_controller, &TestController::resume);
    connect(m_controls, &ControlBar::stopRequested, this, &MainWindow::requestStop);
    connect(m_controls, &ControlBar::emergencyHoldRequested, m_controller, [this] {
        if (m_preflight) { // nothing may start from the dialog, nothing is armed
            m_pendingRun = RunRequest::None;
            m_preflight->reject();
        }
        m_controller->emergencyHold();
    });
    connect(m_controls, &ControlBar::paceChanged, m_controller,
            [this](double factor, double wallPerStep) {
                m_controller->setWallTimePerStep(wallPerStep);
                m_controller->setSpeed(factor);
            });
    m_controller->setSpeed(m_controls->speed());
    connect(m_setup, &SetupPanel::applyRequested, this, &MainWindow::applySetup);
    connect(m_setup, &SetupPanel::groundMotionChosen, this, &MainWindow::previewGroundMotion);
    connect(m_setup, &SetupPanel::testLinkRequested, this, &MainWindow::testLink);

    connect(m_parameters, &ParametersPanel::boundsEdited, m_controller,
            &TestController::setParameterBounds);
    connect(m_parameters, &ParametersPanel::lockEdited, m_controller,
            &TestController::setParameterLocked);
    connect(m_parameters, &ParametersPanel::thresholdEdited, m_controller,
            &TestController::setFitThreshold);
    connect(m_parameters, &ParametersPanel::editRefused, this,
            [this](const QString& why) { m_alarms->addMessage(why, AlarmSeverity::Warning); });
    connect(m_pending, &PendingUpdatesPanel::approveRequested, m_controller,
            &TestController::approveUpdate);
    connect(m_pending, &PendingUpdatesPanel::rejectRequested, m_controller,
            &TestController::rejectUpdate);
    connect(m_pending, &PendingUpdatesPanel::approveOffsetsRequested, m_controller,
            &TestController::approveOffsets);
    connect(m_pending, &PendingUpdatesPanel::rejectOffsetsRequested, m_controller,
            &TestController::rejectOffsets);
    connect(m_pending, &PendingUpdatesPanel::policyChosen, this, &MainWindow::onPolicyChosen);
    connect(m_controller, &TestController::operatorEvent, this,
            [this](const OperatorEvent& e) { m_alarms->addEvent(e); });

    connect(m_controller, &TestController::testLoaded, this, &MainWindow::onTestLoaded);
    connect(m_controller, &TestController::recordsArrived, m_plots,
            [this](const std::vector<StepRecord>& rows) {
                m_plots->appendRecords(rows);
                m_plots->refresh(); // coalesced and budgeted by the panel
            });
    connect(m_controller, &TestController::stateChanged, this, &MainWindow::onStateChanged);
    connect(m_controller, &TestController::progress, m_status, &TestStatusBar::setProgress);
    connect(m_controller, &TestController::progress, this,
            [this](int step, int, double time, double) { m_lastProgress = {step, time}; });
    connect(m_controller, &TestController::alarmRaised, this, &MainWindow::onAlarm);
    connect(m_controller, &TestController::updatingChanged, m_parameters,
            &ParametersPanel::setSnapshot);
    connect(m_controller, &TestController::updatingChanged, m_pending,
            &PendingUpdatesPanel::setSnapshot);
    // The plots draw the bounds and the threshold in force (an accepted edit redraws them).
    connect(m_controller, &TestController::updatingChanged, m_plots,
            [this](const UpdatingSnapshot& s) {
                if (!s.enabled)
                    return;
                for (const ParameterState& p : s.parameters)
                    m_plots->setParameterBounds(QString::fromStdString(p.name), p.bounds.lower,
                                                p.bounds.upper);
                if (s.fitThreshold > 0.0 && s.fitThreshold != m_plots->fitError().threshold()) {
                    m_plots->fitError().setThreshold(s.fitThreshold);
                    m_plots->refresh();
                }
            });
    connect(m_controller, &TestController::commandRefused, this,
            [this](const QString&, const QString& source, const QStringList& args) {
                // Redrawn from the template in a new language, as the other entries.
                m_alarms->addMessage(
                    [source, args] { return TestWorker::refusalText(source, args); },
                    AlarmSeverity::Warning);
                m_status->showMessage(TestWorker::refusalText(source, args), 10000);
            });
    connect(m_controller, &TestController::preflightReady, this, &MainWindow::showPreflight);
    connect(m_controller, &TestController::recordingStarted, m_status,
            &TestStatusBar::setRecordingFile);
}

} // namespace hsmu::gui
