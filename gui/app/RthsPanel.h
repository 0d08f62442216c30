#pragma once
// RthsPanel: the console's RTHS view (docs/console.md, "Real-time hybrid simulation"; docs/rths.md,
// "The console's RTHS view"), the "Real-time hybrid simulation" dock: the operator picks a
// benchmark case or an RTHS configuration file, the pace (fast or real time) and a duration,
// starts the run on the built-in virtual lab (RthsSession) and sees
//   - the synchronization plot, measured against desired displacement [mm];
//   - the moving window's delay [ms] and amplitude error [%] over time [s];
//   - live J1 [ms] and J2 [%] with their warning and critical thresholds (editable during the
//     run, effective at the next estimate): crossing one raises an alarm in the alarm panel;
//   - Hold and Emergency hold, which hold the running loop before its next tick, and Resume,
//     which lets a held run go on from there (a limit still breached refuses it); a run held by
//     the loop itself (a limit of the plant or command, deadline misses) is named in the panel
//     and as a critical alarm with its channel, value and tick;
//   - the damper twin of a run with one (RthsTwinPanel): its parameters as the loop has them,
//     with units and bounds, and new values the operator sends (checked against the bounds
//     first), applied before the loop's next tick, locally or over the link (rths-update);
//   - the record folder (default: the console's record folder + "/rths"; empty: not recorded)
//     and where the run's record goes (the first free record.h5, record-N.h5 there), or, for a
//     controller's run, where the controller records (its hello-ack) or that it does not.
// The estimates and the thresholds' logic are core's (rths::TrackingWindow, TrackingAlarms):
// this panel only feeds them the session's samples and shows what they return.
// Thread rules: GUI thread only.

#include "core/rths/TrackingAlarms.h"
#include "core/rths/TrackingWindow.h"
#include "gui/app/RthsSession.h"

#include <QWidget>

#include <functional>
#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QTabWidget;
class QToolButton;

namespace hsmu::gui {

class AlarmList;
class RthsTwinPanel;
class SynchronizationPlot;
class TrackingHistoryPlot;

class RthsPanel : public QWidget {
    Q_OBJECT
public:
    /// alarms: the main window's alarm list (threshold alarms, holds, errors go there).
    explicit RthsPanel(AlarmList* alarms, QWidget* parent = nullptr);

    /// The moving window of the live estimates (default: 1 s, every 0.1 s, delays to 50 ms),
    /// gated for the displacement sensor of cfg: no estimate while the window's command RMS is
    /// below 10 x the sensor's noise RMS (noise and quantization) or 0.1 x the run's largest.
    static rths::TrackingWindowSettings windowSettings(const RthsConfig& cfg);

    /// Start a run of cfg over ag [m/s^2] (what the Start button does after loading the chosen
    /// source); false with the reason shown (and listed as an alarm) when it cannot start.
    bool startRun(const RthsConfig& cfg, const GroundMotion& ag, RthsSession::Pace pace, double duration);
    /// Monitor the loop `hsmu-controller --rths` runs at host:port (the controller runs its own
    /// copy of cfg; token: its hello's); what Start does with a tcp:// address in Controller.
    bool startRemoteRun(const RthsConfig& cfg, const QString& host, quint16 port, const QString& token,
                        double duration);
    /// Load the chosen source (benchmark case or file) and start it (locally, or as the monitor
    /// of the controller named in the Controller field; its token from HSMU_CONTROLLER_TOKEN).
    void start();
    void hold();
    void emergencyHold();
    /// Go on with the held run from the tick where it held (docs/rths.md, "Hold and resume");
    /// a refusal (a limit still breached) is shown and listed with its reason.
    void resume();
    bool running() const { return m_session->running(); }

    /// The console's record folder (ConsoleSettings::recordDirectory()) + "/rths"; "" when the
    /// console records nothing.
    static QString defaultRecordFolder();
    /// Where the next local run records ("" = not recorded).
    void setRecordFolder(const QString& folder);
    QString recordFolder() const;
    /// The record line: where the run records, recorded, or where the controller records.
    QString recordText() const;

    void setLimits(const rths::TrackingLimits& limits);
    rths::TrackingLimits limits() const { return m_alarmsLogic.limits(); }

    RthsSession* session() const { return m_session; }
    SynchronizationPlot* synchronizationPlot() const { return m_sync; }
    TrackingHistoryPlot* historyPlot() const { return m_history; }
    RthsTwinPanel* twinPanel() const { return m_twin; }
    /// The last live estimate (hasEstimate() false before the first).
    const rths::TrackingWindow& window() const { return *m_window; }
    QString statusText() const;

signals:
    /// The run ended (hold: why it stopped early, "" when it ran out).
    void runFinished(const QString& hold);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void onSamples(const std::vector<comms::TelemetrySample>& batch);
    void onFinished(const QString& hold, const rths::BenchmarkCriteria& criteria, long ticks);
    void onLimitsEdited();
    void onFailed(const QString& why);
    /// Clear the plots and estimates of the last run (the window gated for cfg's displacement
    /// sensor: rths::gatedWindowSettings); the status says what runs.
    void began(const RthsConfig& cfg, const QString& where);
    void showEstimate();
    void setStatus(std::function<QString()> render, bool bad);
    void setRecordState(std::function<QString()> render);
    void onControllerDescribed(const QString& description);
    void onTwinUpdateRequested(const rths::TwinUpdate& update);
    void onTwinUpdates(const std::vector<UpdateEvent>& events);
    void onProposalDecided(int id, bool approve);
    void updateButtons();
    void browse();

    AlarmList* m_alarms;
    RthsSession* m_session;
    std::unique_ptr<rths::TrackingWindow> m_window;
    rths::TrackingAlarms m_alarmsLogic;
    double m_lastTime = 0.0;
    long m_lastTick = 0;
    double m_rate = 1.0; ///< the run's loop rate [Hz]

    QLabel* m_sourceLabel = nullptr;
    QComboBox* m_source = nullptr;
    QLineEdit* m_file = nullptr;
    QToolButton* m_browse = nullptr;
    QLabel* m_controllerLabel = nullptr;
    QLineEdit* m_controller = nullptr;
    QLabel* m_paceLabel = nullptr;
    QComboBox* m_pace = nullptr;
    QLabel* m_durationLabel = nullptr;
    QDoubleSpinBox* m_duration = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_hold = nullptr;
    QPushButton* m_emergency = nullptr;
    QPushButton* m_resume = nullptr;
    QLabel* m_j1Label = nullptr;
    QLabel* m_j2Label = nullptr;
    QDoubleSpinBox* m_j1Warning = nullptr;
    QDoubleSpinBox* m_j1Critical = nullptr;
    QDoubleSpinBox* m_j2Warning = nullptr;
    QDoubleSpinBox* m_j2Critical = nullptr;
    QLabel* m_thresholdHeader = nullptr;
    QLabel* m_warningHeader = nullptr;
    QLabel* m_criticalHeader = nullptr;
    QLabel* m_j1Value = nullptr;
    QLabel* m_j2Value = nullptr;
    QLabel* m_amplitudeValue = nullptr;
    QLabel* m_timeValue = nullptr;
    QLabel* m_recordLabel = nullptr;
    QLineEdit* m_recordFolder = nullptr;
    QLabel* m_recordState = nullptr;
    std::function<QString()> m_recordRender; // the record line, again at each language change
    QLabel* m_status = nullptr;
    std::function<QString()> m_statusRender; // the status line, again at each language change
    bool m_statusBad = false;
    SynchronizationPlot* m_sync = nullptr;
    TrackingHistoryPlot* m_history = nullptr;
    RthsTwinPanel* m_twin = nullptr;
    QTabWidget* m_tabs = nullptr;
};

} // namespace hsmu::gui
