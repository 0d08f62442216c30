#include "gui/app/RthsPanel.h"

#include "comms/LinkAddress.h"
#include "gui/app/AlarmList.h"
#include "gui/app/ConsoleSettings.h"
#include "gui/app/RthsTwinPanel.h"
#include "gui/plots/RthsPlots.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFileDialog>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace hsmu::gui {

namespace {

QDoubleSpinBox* thresholdBox(const QString& suffix, double value, QWidget* parent)
{
    auto* b = new QDoubleSpinBox(parent);
    b->setRange(0.0, 1000.0);
    b->setDecimals(2);
    b->setSingleStep(0.5);
    b->setSuffix(suffix);
    b->setValue(value);
    return b;
}

/// The alarm a hold is listed as: the operator's (acknowledged at once), the emergency hold
/// (critical), or the loop's own (a limit, deadline misses: critical).
Alarm holdAlarm(const std::string& hold, double time, long tick)
{
    const bool operatorHold = hold.rfind("console hold", 0) == 0;
    const bool emergency = hold.rfind("emergency hold", 0) == 0;
    const bool deadline = hold.find("deadline") != std::string::npos;
    return Alarm(time, int(tick), operatorHold ? AlarmSeverity::Warning : AlarmSeverity::Critical,
                 operatorHold || emergency ? AlarmKind::OperatorHold
                 : deadline               ? AlarmKind::ControlFault
                                          : AlarmKind::LimitExceeded,
                 "RTHS run held: " + hold, "rths-held", {hold});
}

} // namespace

rths::TrackingWindowSettings RthsPanel::windowSettings(const RthsConfig& cfg)
{
    return rths::gatedWindowSettings({1.0, 0.1, 0.05}, cfg.settings.sensors);
}

RthsPanel::RthsPanel(AlarmList* alarms, QWidget* parent)
    : QWidget(parent), m_alarms(alarms), m_session(new RthsSession(this))
{
    auto* v = new QVBoxLayout(this);
    auto* form = new QGridLayout;
    m_sourceLabel = new QLabel(this);
    m_source = new QComboBox(this);
    for (int c = 1; c <= 4; ++c)
        m_source->addItem(QString(), QStringLiteral("rths-benchmark-case-%1").arg(c));
    m_source->addItem(QString(), QString());
    m_file = new QLineEdit(this);
    m_browse = new QToolButton(this);
    m_browse->setText(QStringLiteral("..."));
    m_paceLabel = new QLabel(this);
    m_pace = new QComboBox(this);
    m_pace->addItem(QString());
    m_pace->addItem(QString());
    m_durationLabel = new QLabel(this);
    m_duration = new QDoubleSpinBox(this);
    m_duration->setRange(0.0, 3600.0);
    m_duration->setDecimals(1);
    m_duration->setSuffix(QStringLiteral(" s"));
    form->addWidget(m_sourceLabel, 0, 0);
    form->addWidget(m_source, 0, 1);
    form->addWidget(m_file, 0, 2);
    form->addWidget(m_browse, 0, 3);
    m_controllerLabel = new QLabel(this);
    m_controller = new QLineEdit(this);
    m_controller->setObjectName(QStringLiteral("rthsController"));
    // One field per row under the source (the dock stays narrow enough for 1280x720).
    form->addWidget(m_paceLabel, 1, 0);
    form->addWidget(m_pace, 1, 1);
    form->addWidget(m_durationLabel, 2, 0);
    form->addWidget(m_duration, 2, 1);
    form->addWidget(m_controllerLabel, 3, 0);
    form->addWidget(m_controller, 3, 1, 1, 3);
    m_recordLabel = new QLabel(this);
    m_recordFolder = new QLineEdit(defaultRecordFolder(), this);
    m_recordFolder->setObjectName(QStringLiteral("rthsRecordFolder"));
    m_recordState = new QLabel(this);
    m_recordState->setObjectName(QStringLiteral("rthsRecordState"));
    m_recordState->setWordWrap(true);
    m_recordState->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addWidget(m_recordLabel, 4, 0);
    form->addWidget(m_recordFolder, 4, 1, 1, 3);
    form->addWidget(m_recordState, 5, 0, 1, 4);
    v->addLayout(form);

    auto* buttons = new QGridLayout; // two by two: Start, Hold / Resume, Emergency hold
    m_start = new QPushButton(this);
    m_hold = new QPushButton(this);
    m_emergency = new QPushButton(this);
    m_resume = new QPushButton(this);
    m_emergency->setStyleSheet(QStringLiteral("QPushButton { color: white; background: #b00000; font-weight: bold; }"
                                              "QPushButton:disabled { color: #f0e0e0; background: #d8a8a8; }"));
    m_source->setObjectName(QStringLiteral("rthsSource"));
    m_file->setObjectName(QStringLiteral("rthsFile"));
    m_pace->setObjectName(QStringLiteral("rthsPace"));
    m_duration->setObjectName(QStringLiteral("rthsDuration"));
    m_start->setObjectName(QStringLiteral("rthsStart"));
    m_hold->setObjectName(QStringLiteral("rthsHold"));
    m_emergency->setObjectName(QStringLiteral("rthsEmergencyHold"));
    m_resume->setObjectName(QStringLiteral("rthsResume"));
    buttons->addWidget(m_start, 0, 0);
    buttons->addWidget(m_hold, 0, 1);
    buttons->addWidget(m_resume, 1, 0);
    buttons->addWidget(m_emergency, 1, 1);
    v->addLayout(buttons);

    // Live values and their thresholds: one row per index.
    const rths::TrackingLimits l = m_alarmsLogic.limits();
    auto* grid = new QGridLayout;
    m_thresholdHeader = new QLabel(this);
    m_warningHeader = new QLabel(this);
    m_criticalHeader = new QLabel(this);
    m_j1Label = new QLabel(this);
    m_j2Label = new QLabel(this);
    m_j1Value = new QLabel(this);
    m_j2Value = new QLabel(this);
    m_amplitudeValue = new QLabel(this);
    m_timeValue = new QLabel(this);
    for (QLabel* header : {m_warningHeader, m_criticalHeader, m_j2Label})
        header->setWordWrap(true); // long in some languages: wrap instead of widening the dock
    for (QLabel* value : {m_j1Value, m_j2Value})
        value->setStyleSheet(QStringLiteral("font-size: 14pt; font-weight: bold;"));
    m_j1Warning = thresholdBox(QStringLiteral(" ms"), l.j1Warning, this);
    m_j1Critical = thresholdBox(QStringLiteral(" ms"), l.j1Critical, this);
    m_j2Warning = thresholdBox(QStringLiteral(" %"), l.j2Warning, this);
    m_j2Critical = thresholdBox(QStringLiteral(" %"), l.j2Critical, this);
    grid->addWidget(m_thresholdHeader, 0, 0);
    grid->addWidget(m_warningHeader, 0, 2);
    grid->addWidget(m_criticalHeader, 0, 3);
    grid->addWidget(m_j1Label, 1, 0);
    grid->addWidget(m_j1Value, 1, 1);
    grid->addWidget(m_j1Warning, 1, 2);
    grid->addWidget(m_j1Critical, 1, 3);
    grid->addWidget(m_j2Label, 2, 0);
    grid->addWidget(m_j2Value, 2, 1);
    grid->addWidget(m_j2Warning, 2, 2);
    grid->addWidget(m_j2Critical, 2, 3);
    grid->addWidget(m_amplitudeValue, 3, 0, 1, 2);
    grid->addWidget(m_timeValue, 3, 2, 1, 2);
    v->addLayout(grid);

    m_status = new QLabel(this);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    v->addWidget(m_status);


    // The plots and the damper twin share the height (one tab each): the view fits the
    // console's 1280x720 design size (the main window puts the panel in a scroll area too).
    m_tabs = new QTabWidget(this);
    m_tabs->setObjectName(QStringLiteral("rthsTabs"));
    auto* plots = new QWidget(m_tabs);
    auto* pv = new QVBoxLayout(plots);
    pv->setContentsMargins(0, 0, 0, 0);
    m_sync = new SynchronizationPlot(plots);
    m_history = new TrackingHistoryPlot(plots);
    m_history->setDelayThresholds(l.j1Warning, l.j1Critical);
    pv->addWidget(m_sync, 3);
    pv->addWidget(m_history, 2);
    m_twin = new RthsTwinPanel(m_tabs);
    m_tabs->addTab(plots, QString());
    m_tabs->addTab(m_twin, QString());
    v->addWidget(m_tabs, 1);

    connect(m_start, &QPushButton::clicked, this, &RthsPanel::start);
    connect(m_hold, &QPushButton::clicked, this, &RthsPanel::hold);
    connect(m_emergency, &QPushButton::clicked, this, &RthsPanel::emergencyHold);
    connect(m_resume, &QPushButton::clicked, this, &RthsPanel::resume);
    connect(m_browse, &QToolButton::clicked, this, &RthsPanel::browse);
    connect(m_source, &QComboBox::currentIndexChanged, this, &RthsPanel::updateButtons);
    for (QDoubleSpinBox* b : {m_j1Warning, m_j1Critical, m_j2Warning, m_j2Critical})
        connect(b, &QDoubleSpinBox::valueChanged, this, &RthsPanel::onLimitsEdited);
    connect(m_session, &RthsSession::samples, this, &RthsPanel::onSamples);
    connect(m_session, &RthsSession::finished, this, &RthsPanel::onFinished);
    connect(m_session, &RthsSession::failed, this, &RthsPanel::onFailed);
    connect(m_session, &RthsSession::controllerDescribed, this, &RthsPanel::onControllerDescribed);
    connect(m_session, &RthsSession::twinUpdates, this, &RthsPanel::onTwinUpdates);
    connect(m_twin, &RthsTwinPanel::updateRequested, this, &RthsPanel::onTwinUpdateRequested);
    connect(m_twin, &RthsTwinPanel::decisionRequested, this, &RthsPanel::onProposalDecided);
    setStatus([] { return tr("No RTHS run yet."); }, false);
    retranslateUi();
    showEstimate();
    updateButtons();
}

void RthsPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

void RthsPanel::retranslateUi()
{
    m_sourceLabel->setText(tr("Run:"));
    for (int c = 0; c < 4; ++c)
        m_source->setItemText(c, tr("Benchmark case %1").arg(c + 1));
    m_source->setItemText(4, tr("Configuration file"));
    m_file->setPlaceholderText(tr("RTHS configuration (.json)"));
    m_browse->setToolTip(tr("Choose an RTHS configuration file"));
    m_controllerLabel->setText(tr("Controller:"));
    m_controller->setPlaceholderText(tr("built-in virtual lab, or tcp://HOST:PORT of hsmu-controller --rths"));
    m_controller->setToolTip(tr("Empty: the loop runs in the console. tcp://HOST:PORT: monitor the loop hsmu-controller --rths runs (its token from HSMU_CONTROLLER_TOKEN)"));
    m_paceLabel->setText(tr("Pace:"));
    m_pace->setItemText(0, tr("Fast (simulated)"));
    m_pace->setItemText(1, tr("Real time"));
    m_durationLabel->setText(tr("Duration:"));
    m_duration->setSpecialValueText(tr("whole record"));
    m_duration->setToolTip(tr("Stop the run after this many seconds of test time (0: the whole record)"));
    m_start->setText(tr("Start RTHS"));
    m_hold->setText(tr("Hold"));
    m_hold->setToolTip(tr("Hold the loop before its next tick (Resume goes on from there)"));
    m_resume->setText(tr("Resume"));
    m_resume->setToolTip(tr("Go on with the held run from the tick where it held (refused while a limit is still breached)"));
    m_emergency->setText(tr("Emergency hold"));
    m_thresholdHeader->setText(tr("Live tracking"));
    m_warningHeader->setText(tr("Warning above"));
    m_criticalHeader->setText(tr("Critical above"));
    m_j1Label->setText(tr("J1 delay"));
    m_j2Label->setText(tr("J2 tracking error"));
    m_tabs->setTabText(0, tr("Tracking"));
    m_tabs->setTabText(1, tr("Damper twin"));
    m_recordLabel->setText(tr("Record folder:"));
    m_recordFolder->setPlaceholderText(tr("not recorded"));
    m_recordFolder->setToolTip(tr("Every tick of a run from this view goes to record.h5 in this folder (record-2.h5, record-3.h5, ... when taken: nothing is overwritten); empty: not recorded"));
    m_recordState->setText(m_recordRender ? m_recordRender() : QString());
    m_status->setText(m_statusRender ? m_statusRender() : QString());
    showEstimate();
}

QString RthsPanel::defaultRecordFolder()
{
    const QString dir = ConsoleSettings::recordDirectory();
    return dir.isEmpty() ? QString() : dir + QStringLiteral("/rths");
}

void RthsPanel::setRecordFolder(const QString& folder)
{
    m_recordFolder->setText(folder);
}

QString RthsPanel::recordFolder() const
{
    return m_recordFolder->text().trimmed();
}

QString RthsPanel::recordText() const
{
    return m_recordState->text();
}

void RthsPanel::setRecordState(std::function<QString()> render)
{
    m_recordRender = std::move(render);
    m_recordState->setText(m_recordRender());
}

void RthsPanel::onControllerDescribed(const QString& description)
{
    setRecordState([description] { return tr("Recorded on the controller, not by the console: %1").arg(description); });
}

void RthsPanel::setStatus(std::function<QString()> render, bool bad)
{
    m_statusRender = std::move(render);
    m_statusBad = bad;
    m_status->setStyleSheet(bad ? QStringLiteral("color: #b00000; font-weight: bold;") : QString());
    m_status->setText(m_statusRender());
}

QString RthsPanel::statusText() const
{
    return m_status->text();
}

void RthsPanel::updateButtons()
{
    const bool going = m_session->running();
    const bool file = m_source->currentIndex() == 4;
    m_start->setEnabled(!going);
    m_hold->setEnabled(going);
    m_emergency->setEnabled(going);
    m_resume->setEnabled(m_session->resumable());
    m_source->setEnabled(!going);
    m_file->setEnabled(!going && file);
    m_browse->setEnabled(!going && file);
    m_pace->setEnabled(!going);
    m_controller->setEnabled(!going);
    m_duration->setEnabled(!going);
    m_recordFolder->setEnabled(!going);
    m_twin->setRunning(going);
}

void RthsPanel::browse()
{
    const QString path = QFileDialog::getOpenFileName(this, tr("RTHS configuration"), m_file->text(),
                                                      tr("Configuration (*.json)"));
    if (!path.isEmpty())
        m_file->setText(path);
}

void RthsPanel::start()
{
    const QString name = m_source->currentIndex() == 4 ? m_file->text() : m_source->currentData().toString();
    try {
        if (name.isEmpty())
            throw std::runtime_error(tr("choose an RTHS configuration file").toStdString());
        const RthsConfig cfg = loadRthsConfig(name.toStdString());
        if (const QString address = m_controller->text().trimmed(); !address.isEmpty()) {
            std::string error;
            const auto a = comms::LinkAddress::parse(address.toStdString(), &error);
            if (!a || a->kind != comms::LinkAddress::Kind::Tcp)
                throw std::runtime_error(tr("controller: an RTHS loop is monitored over tcp://HOST:PORT (hsmu-controller --rths)").toStdString() +
                                         (error.empty() ? std::string() : " (" + error + ")"));
            startRemoteRun(cfg, QString::fromStdString(a->host), a->port, qEnvironmentVariable("HSMU_CONTROLLER_TOKEN"),
                           m_duration->value());
            return;
        }
        const GroundMotion ag = loadRthsGroundMotion(cfg, std::string(), cfg.groundMotionScale);
        startRun(cfg, ag, m_pace->currentIndex() == 1 ? RthsSession::Pace::RealTime : RthsSession::Pace::Fast,
                 m_duration->value());
    } catch (const std::exception& e) {
        const QString why = QString::fromStdString(e.what());
        setStatus([why] { return tr("Cannot start the RTHS run: %1").arg(why); }, true);
        m_alarms->addMessage([why] { return tr("Cannot start the RTHS run: %1").arg(why); }, AlarmSeverity::Warning);
    }
}

bool RthsPanel::startRun(const RthsConfig& cfg, const GroundMotion& ag, RthsSession::Pace pace, double duration)
{
    QString error;
    if (!m_session->start(cfg, ag, pace, duration, recordFolder(), &error)) {
        setStatus([error] { return tr("Cannot start the RTHS run: %1").arg(error); }, true);
        m_alarms->addMessage([error] { return tr("Cannot start the RTHS run: %1").arg(error); }, AlarmSeverity::Warning);
        return false;
    }
    const QString pre = m_session->preflight();
    const bool realTime = pace == RthsSession::Pace::RealTime;
    began(cfg,
          realTime ? tr("real time; pre-flight: %1").arg(pre) : tr("fast; pre-flight: %1").arg(pre));
    const QString path = m_session->recordPath();
    if (path.isEmpty())
        setRecordState([] { return tr("Not recorded (no record folder)"); });
    else
        setRecordState([path] { return tr("Recording every tick to %1").arg(path); });
    return true;
}

bool RthsPanel::startRemoteRun(const RthsConfig& cfg, const QString& host, quint16 port, const QString& token,
                               double duration)
{
    QString error;
    if (!m_session->startRemote(cfg, host, port, token, duration, &error)) {
        setStatus([error] { return tr("Cannot start the RTHS run: %1").arg(error); }, true);
        return false;
    }
    began(cfg, tr("on the controller %1:%2").arg(host).arg(port));
    setRecordState([] { return tr("Recorded on the controller, not by the console (waiting for the controller's description)"); });
    return true;
}

void RthsPanel::began(const RthsConfig& cfg, const QString& where)
{
    const QString name = QString::fromStdString(cfg.name);
    const double rate = cfg.settings.rate;
    m_window = std::make_unique<rths::TrackingWindow>(m_session->samplePeriod(), windowSettings(cfg));
    m_alarmsLogic.reset();
    m_sync->clearData();
    m_history->clearData();
    m_lastTime = 0.0;
    m_lastTick = 0;
    m_rate = rate;
    m_twin->setTwin(cfg.settings.damper, rate);
    setStatus([name, rate, where] { return tr("Running '%1' at %2 Hz (%3)").arg(name).arg(rate).arg(where); }, false);
    m_alarms->addMessage([name] { return tr("RTHS run '%1' started").arg(name); }, AlarmSeverity::Info);
    showEstimate();
    updateButtons();
}

void RthsPanel::onFailed(const QString& why)
{
    setStatus([why] { return tr("The RTHS run could not be followed: %1").arg(why); }, true);
    m_alarms->addAlarm(Alarm(m_lastTime, int(m_lastTick), AlarmSeverity::Critical, AlarmKind::ControlFault,
                             "RTHS run not followed: " + why.toStdString(), "rths-not-followed", {why.toStdString()}));
    updateButtons();
    emit runFinished(why);
}

void RthsPanel::onTwinUpdateRequested(const rths::TwinUpdate& update)
{
    QString why;
    if (!m_session->sendTwinUpdate(update, &why))
        m_twin->showNotSent(why);
}

void RthsPanel::onProposalDecided(int id, bool approve)
{
    QString why;
    if (!m_session->decideProposal(id, approve, &why))
        m_twin->showNotSent(why);
    else
        m_alarms->addEvent(m_lastTime, int(m_lastTick),
                           approve ? tr("RTHS proposal #%1 approved").arg(id) : tr("RTHS proposal #%1 rejected").arg(id));
}

void RthsPanel::onTwinUpdates(const std::vector<UpdateEvent>& events)
{
    m_twin->showDecisions(events);
    for (UpdateEvent e : events) {
        if (e.proposal != 0 && (e.decision == UpdateDecision::Applied || e.decision == UpdateDecision::Refused))
            continue; // listed once, as the update's decision
        e.time = double(e.step) / m_rate; // a controller's decision carries its tick only
        const QString text = e.step > 0 || e.ok ? QString::fromStdString(rths::describeTwinUpdate(e))
                                                : QStringLiteral("damper twin update refused: %1").arg(QString::fromStdString(e.message));
        m_alarms->addMessage(double(e.step) / m_rate, e.step, [text] { return text; },
                             e.ok ? AlarmSeverity::Info : AlarmSeverity::Warning);
    }
}

void RthsPanel::hold()
{
    if (!m_session->running())
        return;
    m_session->hold();
    m_alarms->addEvent(m_lastTime, int(m_lastTick), tr("RTHS hold"));
}

void RthsPanel::emergencyHold()
{
    if (!m_session->running())
        return;
    m_session->emergencyHold();
    m_alarms->addEvent(m_lastTime, int(m_lastTick), tr("RTHS emergency hold"));
}

void RthsPanel::resume()
{
    QString why;
    if (!m_session->resume(&why)) {
        setStatus([why] { return tr("Not resumed: %1").arg(why); }, true);
        m_alarms->addMessage(m_lastTime, int(m_lastTick), [why] { return tr("RTHS run not resumed: %1").arg(why); },
                             AlarmSeverity::Warning);
        updateButtons();
        return;
    }
    m_alarms->addEvent(m_lastTime, int(m_lastTick), tr("RTHS resume"));
    setStatus([] { return tr("Resumed"); }, false);
    updateButtons();
}

void RthsPanel::setLimits(const rths::TrackingLimits& l)
{
    m_j1Warning->setValue(l.j1Warning);
    m_j1Critical->setValue(l.j1Critical);
    m_j2Warning->setValue(l.j2Warning);
    m_j2Critical->setValue(l.j2Critical);
}

void RthsPanel::onLimitsEdited()
{
    const rths::TrackingLimits l{m_j1Warning->value(), m_j1Critical->value(), m_j2Warning->value(),
                                 m_j2Critical->value()};
    const std::string bad = rths::checkTrackingLimits(l);
    for (QDoubleSpinBox* b : {m_j1Warning, m_j1Critical, m_j2Warning, m_j2Critical})
        b->setStyleSheet(bad.empty() ? QString() : QStringLiteral("background: #ffd0d0;"));
    if (!bad.empty()) {
        const QString why = QString::fromStdString(bad);
        for (QDoubleSpinBox* b : {m_j1Warning, m_j1Critical, m_j2Warning, m_j2Critical})
            b->setToolTip(tr("Not applied: %1").arg(why));
        return; // the last usable thresholds stay in force
    }
    for (QDoubleSpinBox* b : {m_j1Warning, m_j1Critical, m_j2Warning, m_j2Critical})
        b->setToolTip(QString());
    m_alarmsLogic.setLimits(l);
    m_history->setDelayThresholds(l.j1Warning, l.j1Critical);
}

void RthsPanel::onSamples(const std::vector<comms::TelemetrySample>& batch)
{
    std::vector<Alarm> raised;
    for (const auto& s : batch) {
        m_sync->append(s.desired, s.measured);
        m_lastTime = s.time;
        m_lastTick = s.tick;
        if (m_window && m_window->add(s.tick, s.desired, s.measured)) {
            // The window counts samples; the estimate is stamped with the loop's tick and time.
            rths::TrackingEstimate e = m_window->last();
            e.tick = s.tick;
            e.time = s.time;
            if (e.valid) // a gated window (too quiet) leaves a gap
                m_history->append(e.time, e.delay, e.amplitudeError);
            m_alarmsLogic.judge(e, raised);
        }
    }
    for (const Alarm& a : raised)
        m_alarms->addAlarm(a);
    showEstimate();
    m_sync->refresh();
    m_history->refresh();
}

void RthsPanel::showEstimate()
{
    const bool quiet = m_window && m_window->hasEstimate() && !m_window->last().valid;
    const bool has = m_window && m_window->hasEstimate() && !quiet;
    const rths::TrackingEstimate e = m_window && m_window->hasEstimate() ? m_window->last() : rths::TrackingEstimate{};
    const auto colour = [](int level) {
        return level == 2 ? QStringLiteral("color: #b00000;") : level == 1 ? QStringLiteral("color: #c07000;") : QString();
    };
    m_j1Value->setText(has ? tr("%1 ms").arg(e.delay, 0, 'f', 2) : tr("-- ms"));
    m_j2Value->setText(has ? tr("%1 %").arg(e.j2, 0, 'f', 2) : tr("-- %"));
    m_j1Value->setStyleSheet(QStringLiteral("font-size: 14pt; font-weight: bold;") + colour(m_alarmsLogic.j1Level()));
    m_j2Value->setStyleSheet(QStringLiteral("font-size: 14pt; font-weight: bold;") + colour(m_alarmsLogic.j2Level()));
    m_amplitudeValue->setText(has ? tr("Amplitude error: %1 %").arg(e.amplitudeError, 0, 'f', 2)
                              : quiet ? tr("No estimate: the command's RMS %1 mm is below %2 mm")
                                            .arg(e.commandRms * 1e3, 0, 'f', 3).arg(e.gate * 1e3, 0, 'f', 3)
                                      : tr("Amplitude error: -- %"));
    m_timeValue->setText(tr("t = %1 s").arg(m_lastTime, 0, 'f', 2));
}

void RthsPanel::onFinished(const QString& hold, const rths::BenchmarkCriteria& criteria, long ticks)
{
    const long last = ticks > 0 ? ticks - 1 : 0;
    const double t = double(last) / m_rate; // the last tick's time [s]
    const double j1 = criteria.j[0], j2 = criteria.j[1];
    if (const QString path = m_session->recordPath(); !path.isEmpty()) {
        const QString bad = m_session->recordError();
        const auto incomplete = [path, bad] { return tr("The record %1 is incomplete: %2").arg(path, bad); };
        if (bad.isEmpty()) {
            setRecordState([path, ticks] { return tr("Recorded %1 ticks to %2").arg(ticks).arg(path); });
        } else {
            setRecordState(incomplete);
            m_alarms->addMessage(incomplete, AlarmSeverity::Warning);
        }
    }
    if (hold.isEmpty()) {
        setStatus([ticks, t, j1, j2] {
            return tr("Finished: %1 ticks (%2 s); whole run J1 %3 ms, J2 %4 %")
                .arg(ticks).arg(t, 0, 'f', 2).arg(j1, 0, 'f', 2).arg(j2, 0, 'f', 2);
        }, false);
        m_alarms->addMessage(t, int(last), [ticks] { return tr("RTHS run finished: %1 ticks").arg(ticks); },
                             AlarmSeverity::Info);
    } else {
        setStatus([hold, ticks] { return tr("Held after %1 ticks: %2").arg(ticks).arg(hold); }, true);
        const Alarm a = holdAlarm(hold.toStdString(), t, last);
        m_alarms->addAlarm(a, a.kind == AlarmKind::OperatorHold && a.severity != AlarmSeverity::Critical);
    }
    updateButtons();
    emit runFinished(hold);
}

} // namespace hsmu::gui
