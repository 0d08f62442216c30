#pragma once
// MainWindow: assembles the console and only wires signals:
//   ControlBar (top): presets, open, start / pause / single step / resume / stop, emergency hold
//   LivePlotsPanel (centre): every live plot (rows ~30 times a second, coalesced budgeted
//     replots), under an attention banner shown while a critical alarm is unacknowledged
//   docks: Test setup and Parameters (right, one tab each: the setup raised when a test is
//     loaded, the parameters when it runs), Pending updates (right), Alarms (bottom); their
//     layout and the window geometry are remembered (ConsoleSettings)
//   TestStatusBar: test time, step, steps/s and time left, state, link per site (from the
//     test's SiteMonitor, showLink()), recording
//   menus: File (open, recent files, open record -> ReplayWindow, add a note to the record
//     (Ctrl+N, TestController::addNote; also after the end), settings, quit), View, Help
//     (the guide, the keyboard shortcuts, About); F5 / F6 / F7 / F10 / Shift+F5 run the
//     tool bar's Start / Pause / Resume / Single step / Stop with their confirmations
// The window fits the available screen (fitToScreen: the designed or remembered geometry).
// Start goes through the pre-flight: the worker prepares the test (connects a link, checks
// stability) and the PreflightDialog must be confirmed before the first step; a command-line
// --start is the operator's confirmation (setConfirmBeforeStart(false)). An emergency hold
// while the pre-flight is open closes it: nothing is armed. Stop and Quit ask for
// confirmation while a test runs ("end the test and keep the data"). Spin boxes and combo
// boxes take the wheel only when focused (WheelGuard). Operator events come back from the
// worker stamped with step and time and go into the alarm and event list.
// Menus and signal wiring: MainWindowWiring.cpp; banner, alarm dock and the end confirmation
// are their own widgets (AttentionBanner, AlarmPanel, EndConfirmation).
// It owns the TestController. Thread rules: GUI thread only.

#include "gui/ConfigOverrides.h"
#include "gui/app/PreflightReport.h"
#include "gui/app/RunState.h"

#include "core/updating/Reporter.h"

#include <QMainWindow>

#include <functional>
#include <optional>
#include <utility>
#include <vector>

class QDockWidget;
class QLabel;
class QMenu;
class QMessageBox;
class QPushButton;

namespace hsmu {
struct StepRecord;
struct Alarm;
} // namespace hsmu

namespace hsmu::gui {

class AlarmList;
class AttentionBanner;
class ControlBar;
class LivePlotsPanel;
class ParametersPanel;
class PendingUpdatesPanel;
class PreflightDialog;
class RthsPanel;
class SetupPanel;
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
    /// false: startTest() starts without the pre-flight dialog (command-line --start).
    void setConfirmBeforeStart(bool confirm) { m_confirmBeforeStart = confirm; }
    /// The controller of the next load, as typed in the setup panel ("builtin",
    /// "tcp://HOST:PORT", ...).
    void setControllerAddress(const QString& address);
    /// The pre-flight dialog while it is open, else nullptr.
    PreflightDialog* preflightDialog() const { return m_preflight; }
    /// The Stop / Quit confirmation while it is open, else nullptr.
    QMessageBox* confirmation() const { return m_confirmation; }
    /// The real-time hybrid simulation view (the "rthsDock" dock; View menu).
    RthsPanel* rthsPanel() const { return m_rths; }
    /// Every keyboard shortcut of the console, one per line (Help > Keyboard shortcuts).
    static QString shortcutsText();

public slots:
    /// Start the loaded test (unapplied setup edits are applied first; a finished or stopped
    /// one is reloaded first), after the pre-flight confirmation.
    void startTest();
    /// One step (from a loaded test: after the pre-flight confirmation).
    void singleStep();
    /// Rebuild the test from the setup panel.
    bool applySetup();
    /// Stop the test; while one runs, only after the operator confirmed ("end and keep data").
    void requestStop();

protected:
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    enum class RunRequest { None, Start, SingleStep };
    /// Keep the whole window (its frame too) inside the screen's available geometry: the
    /// designed 1500x920 or the remembered geometry, shrunk and moved as needed.
    void fitToScreen();
    QDockWidget* addDock(QWidget* panel, const QString& title, const QString& name,
                         Qt::DockWidgetArea area);
    void buildMenus();
    void rebuildRecentMenu();
    /// Ask for an operator note and queue it to the worker (recorded at the current step).
    void askForNote();
    void showShortcuts();
    void showAbout();
    void openGuide();
    void wireController();
    void requestRun(RunRequest request);
    void showPreflight(const PreflightReport& report);
    void openConfigurationFile();
    void openSettings();
    void onTestLoaded();
    void onStateChanged(RunState state, const QString& message);
    void onAlarm(const Alarm& alarm);
    void onAttention(int count, const QString& latest);
    /// The link label's sites (the configuration's, the setup's controller for the rest) and
    /// the test's SiteMonitor: the one source of the link state shown.
    void showLink();
    /// "HSMU Console - <test>" (or without a test), in the current language.
    void showTitle();
    /// The updating policy chosen in the Pending updates panel: the one setting, kept for
    /// every reload of the same configuration.
    void onPolicyChosen(ReporterPolicy policy, int everyN);
    /// Check and plot the ground motion chosen in the setup at once (before any Apply).
    void previewGroundMotion();
    /// "Test link": apply the setup and prepare the test now (connects the controller).
    void testLink();
    void applyPolicyChoice(TestConfig& cfg) const;
    /// Ask "end the test and keep the data?" (non-blocking); then() runs on confirmation.
    void confirmEnd(const QString& objectName, const QString& question, const QString& yes,
                    std::function<void()> then);

    ConfigOverrides m_overrides;
    QString m_source; ///< preset id or file of the loaded test
    bool m_confirmBeforeStart = true;
    RunRequest m_pendingRun = RunRequest::None;
    TestController* m_controller = nullptr;
    ControlBar* m_controls = nullptr;
    LivePlotsPanel* m_plots = nullptr;
    AttentionBanner* m_banner = nullptr;
    SetupPanel* m_setup = nullptr;
    ParametersPanel* m_parameters = nullptr;
    PendingUpdatesPanel* m_pending = nullptr;
    AlarmList* m_alarms = nullptr;
    QDockWidget* m_alarmDock = nullptr;
    RthsPanel* m_rths = nullptr;
    QDockWidget* m_rthsDock = nullptr;
    QDockWidget* m_setupDock = nullptr;
    QDockWidget* m_parametersDock = nullptr;
    TestStatusBar* m_status = nullptr;
    QMenu* m_recentMenu = nullptr;
    QMenu* m_viewMenu = nullptr;
    PreflightDialog* m_preflight = nullptr;
    QMessageBox* m_confirmation = nullptr;
    bool m_closeConfirmed = false;
    bool m_fittedOnShow = false;
    QSize m_fittedSize; ///< the size fitToScreen() chose last
    std::pair<int, double> m_lastProgress{0, 0.0}; ///< step, test time [s] last reported
    std::optional<std::pair<ReporterPolicy, int>> m_policyChoice;
};

} // namespace hsmu::gui
