#include "gui/app/MainWindow.h"

#include "gui/PresetLibrary.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ControlBar.h"
#include "gui/app/TestController.h"
#include "gui/app/TestStatusBar.h"
#include "gui/plots/LivePlotsPanel.h"
#include "gui/replay/ReplayWindow.h"

#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>

namespace hsmu::gui {

MainWindow::MainWindow(const ConfigOverrides& overrides, QWidget* parent)
    : QMainWindow(parent), m_overrides(overrides) {
    setWindowTitle(tr("HSMU Console"));
    m_controller = new TestController(this);
    m_controls = new ControlBar(this);
    addToolBar(Qt::TopToolBarArea, m_controls);
    addAction(m_controls->emergencyHoldAction()); // shortcut alive even if the bar is hidden

    m_plots = new LivePlotsPanel(this);
    setCentralWidget(m_plots);
    menuBar()->addMenu(tr("&File"))->addAction(tr("Open &record..."), this, [this] {
        ReplayWindow::openWithDialog(this);
    });

    m_alarms = new AlarmList(this);
    auto* dock = new QDockWidget(tr("Alarms and events"), this);
    dock->setObjectName(QStringLiteral("alarmDock"));
    dock->setWidget(m_alarms);
    dock->setFeatures(QDockWidget::DockWidgetMovable | QDockWidget::DockWidgetFloatable);
    addDockWidget(Qt::BottomDockWidgetArea, dock);
    resizeDocks({dock}, {110}, Qt::Vertical);

    m_status = new TestStatusBar(this);
    setStatusBar(m_status);

    connect(m_controls, &ControlBar::presetChosen, this,
            [this](const QString& id) { loadConfiguration(id); });
    connect(m_controls, &ControlBar::openRequested, this, &MainWindow::openConfigurationFile);
    connect(m_controls, &ControlBar::startRequested, this, &MainWindow::startTest);
    connect(m_controls, &ControlBar::pauseRequested, m_controller, &TestController::pause);
    connect(m_controls, &ControlBar::resumeRequested, m_controller, &TestController::resume);
    connect(m_controls, &ControlBar::stopRequested, m_controller, &TestController::stop);
    connect(m_controls, &ControlBar::emergencyHoldRequested, m_controller,
            [this] { m_controller->emergencyHold(); });
    connect(m_controls, &ControlBar::speedChanged, m_controller, &TestController::setSpeed);
    m_controller->setSpeed(m_controls->speed());

    connect(m_controller, &TestController::testLoaded, this, &MainWindow::onTestLoaded);
    connect(m_controller, &TestController::recordsArrived, this, &MainWindow::onRecords);
    connect(m_controller, &TestController::stateChanged, this, &MainWindow::onStateChanged);
    connect(m_controller, &TestController::progress, m_status, &TestStatusBar::setProgress);
    connect(m_controller, &TestController::alarmRaised, this, &MainWindow::onAlarm);
    resize(1280, 800);
}

MainWindow::~MainWindow() = default;

bool MainWindow::loadConfiguration(const QString& nameOrPath, QString* error) {
    try {
        TestConfig cfg = PresetLibrary::load(nameOrPath);
        m_overrides.applyTo(cfg);
        m_controller->load(cfg);
    } catch (const std::exception& e) {
        const QString message = QString::fromStdString(e.what());
        m_alarms->addMessage(tr("cannot load %1: %2").arg(nameOrPath, message),
                             AlarmSeverity::Critical);
        m_status->showMessage(message, 10000);
        m_controls->setRunState(m_controller->state());
        m_status->setRunState(m_controller->state());
        if (error)
            *error = message;
        return false;
    }
    m_source = nameOrPath;
    m_controls->selectPreset(PresetLibrary::resourcePath(nameOrPath).isEmpty() ? QString()
                                                                               : nameOrPath);
    return true;
}

void MainWindow::setSpeed(double factor) {
    m_controls->setSpeed(factor);
    m_controller->setSpeed(factor); // exact, even if the selector has no such entry
}

void MainWindow::startTest() {
    const RunState s = m_controller->state();
    if ((s == RunState::Finished || s == RunState::Stopped || s == RunState::Failed) &&
        !m_source.isEmpty() && !loadConfiguration(m_source))
        return;
    m_controller->start();
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

void MainWindow::onTestLoaded() {
    const RunLayout& layout = m_controller->layout();
    m_plots->configure(layout, m_controller->config());
    m_alarms->clear();
    m_alarms->addMessage(tr("loaded %1 (%2)")
                             .arg(QString::fromStdString(m_controller->config().name),
                                  QString::fromStdString(m_controller->config().sourcePath)),
                         AlarmSeverity::Info);
    setWindowTitle(
        tr("HSMU Console - %1").arg(QString::fromStdString(m_controller->config().name)));
    m_status->setProgress(0, 0, 0.0, 0.0);
}

void MainWindow::onRecords(const std::vector<StepRecord>& rows) {
    m_plots->appendRecords(rows);
    m_plots->refresh();
}

void MainWindow::onStateChanged(RunState state, const QString& message) {
    m_controls->setRunState(state);
    m_status->setRunState(state);
    if (!message.isEmpty()) {
        m_status->showMessage(message, 15000);
        if (state == RunState::Failed)
            m_alarms->addMessage(tr("the test cannot start: %1").arg(message),
                                 AlarmSeverity::Critical);
    }
}

void MainWindow::onAlarm(const Alarm& alarm) {
    m_alarms->addAlarm(alarm);
}

} // namespace hsmu::gui
