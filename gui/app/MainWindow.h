#pragma once
// MainWindow: assembles the console: ControlBar (top), the LivePlotsPanel (centre: every live
// plot), the AlarmList (bottom dock), the TestStatusBar and File > Open record... (a
// ReplayWindow). It owns the TestController and only wires
// signals: plots get rows ~30 times a second and replot once per batch.
// Thread rules: GUI thread only.

#include "gui/ConfigOverrides.h"
#include "gui/app/RunState.h"

#include <QMainWindow>

#include <vector>

namespace hsmu {
struct StepRecord;
struct Alarm;
} // namespace hsmu

namespace hsmu::gui {

class AlarmList;
class ControlBar;
class LivePlotsPanel;
class TestController;
class TestStatusBar;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    /// overrides: applied to every configuration loaded (e.g. --ground-motion).
    explicit MainWindow(const ConfigOverrides& overrides = {}, QWidget* parent = nullptr);
    ~MainWindow() override;

    /// Load a preset name or a configuration file. On error: false, the message in the alarm
    /// list, the status bar and *error (if given).
    bool loadConfiguration(const QString& nameOrPath, QString* error = nullptr);
    TestController& controller() { return *m_controller; }
    /// Pacing: test time per wall time (1 = real time, <= 0 as fast as possible).
    void setSpeed(double factor);

public slots:
    /// Start the loaded test; a finished or stopped one is reloaded first.
    void startTest();

private:
    void openConfigurationFile();
    void onTestLoaded();
    void onRecords(const std::vector<StepRecord>& rows);
    void onStateChanged(RunState state, const QString& message);
    void onAlarm(const Alarm& alarm);

    ConfigOverrides m_overrides;
    QString m_source; ///< preset id or file of the loaded test
    TestController* m_controller = nullptr;
    ControlBar* m_controls = nullptr;
    LivePlotsPanel* m_plots = nullptr;
    AlarmList* m_alarms = nullptr;
    TestStatusBar* m_status = nullptr;
};

} // namespace hsmu::gui
