#pragma once
// ControlBar: the operator's tool bar: preset selector, "Open configuration...", Start,
// Pause, Single step, Resume, Stop (keys F5, F6, F10, F7, Shift+F5, in the tool tips), Emergency
// hold (Ctrl+H, shown on the button; application-
// wide and never disabled; a chord, so it cannot be typed by accident into a table or a field,
// unlike Esc) and the pacing: test speed relative to real time from 1/100 x up to as fast
// as possible, or a fixed wall time per step [s] (pseudo-dynamic tests). It only emits requests; MainWindow
// wires them to the TestController and feeds back the RunState to enable the right buttons. Thread
// rules: GUI thread only.

#include "gui/app/RunState.h"

#include <QKeySequence>
#include <QList>
#include <QToolBar>

class QAction;
class QComboBox;
class QDoubleSpinBox;

namespace hsmu::gui {

class ControlBar : public QToolBar {
    Q_OBJECT
public:
    explicit ControlBar(QWidget* parent = nullptr);

    /// Enable the actions that make sense in `state`.
    void setRunState(RunState state);
    /// Select a preset in the selector without emitting presetChosen().
    void selectPreset(const QString& id);
    /// The pacing factor currently selected (<= 0: as fast as possible, or a fixed wall time
    /// per step).
    double speed() const;
    void setSpeed(double factor);
    /// The wall time per step [s] when "fixed wall time per step" is chosen, else 0.
    double wallTimePerStep() const;
    void setWallTimePerStep(double seconds);
    QAction* emergencyHoldAction() const { return m_hold; }
    /// Start (F5), Pause (F6), Resume (F7), Single step (F10), Stop... (Shift+F5): the
    /// window adds them so that their keys work while the bar is hidden.
    QList<QAction*> runActions() const { return {m_start, m_pause, m_resume, m_step, m_stop}; }
    /// The shortcut of the emergency hold.
    static QKeySequence emergencyHoldShortcut();

signals:
    void presetChosen(const QString& id);
    void openRequested();
    void startRequested();
    void pauseRequested();
    void singleStepRequested();
    void resumeRequested();
    void stopRequested();
    void emergencyHoldRequested();
    void speedChanged(double factor);
    /// factor: test time per wall time (0: see wallPerStep); wallPerStep [s] (0: use factor).
    void paceChanged(double factor, double wallPerStep);

private:
    /// The speed selector's text for a pace factor (kWallPerStep: the fixed wall time entry).
    static QString speedText(double factor);
    static constexpr double kWallPerStep = -1.0; ///< the selector's "fixed wall time" item
    void emitPace();

    QComboBox* m_presets = nullptr;
    QDoubleSpinBox* m_wallPerStep = nullptr;
    QAction* m_wallPerStepAction = nullptr;
    QAction* m_speedLabelAction = nullptr; ///< the "Speed:" label
    QComboBox* m_speed = nullptr;
    QAction* m_open = nullptr;
    QAction* m_start = nullptr;
    QAction* m_pause = nullptr;
    QAction* m_step = nullptr;
    QAction* m_resume = nullptr;
    QAction* m_stop = nullptr;
    QAction* m_hold = nullptr;
};

} // namespace hsmu::gui
