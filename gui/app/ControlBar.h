#pragma once
// ControlBar: the operator's tool bar: preset selector, "Open configuration...", Start,
// Pause, Single step, Resume, Stop, Emergency hold (Ctrl+H, shown on the button; application-
// wide and never disabled; a chord, so it cannot be typed by accident into a table or a field,
// unlike Esc) and the pacing (test speed relative to real time). It only emits requests; MainWindow
// wires them to the TestController and feeds back the RunState to enable the right buttons. Thread
// rules: GUI thread only.

#include "gui/app/RunState.h"

#include <QKeySequence>
#include <QToolBar>

class QAction;
class QComboBox;

namespace hsmu::gui {

class ControlBar : public QToolBar {
    Q_OBJECT
public:
    explicit ControlBar(QWidget* parent = nullptr);

    /// Enable the actions that make sense in `state`.
    void setRunState(RunState state);
    /// Select a preset in the selector without emitting presetChosen().
    void selectPreset(const QString& id);
    /// The pacing factor currently selected (<= 0: as fast as possible).
    double speed() const;
    void setSpeed(double factor);
    QAction* emergencyHoldAction() const { return m_hold; }
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

private:
    QComboBox* m_presets = nullptr;
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
