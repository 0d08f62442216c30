#pragma once
// TestStatusBar: test time [s], step (of total), steps per second and the run state, always
// visible at the bottom of the main window. Temporary messages use QStatusBar::showMessage.
// Thread rules: GUI thread only.

#include "gui/app/RunState.h"

#include <QStatusBar>

class QLabel;

namespace hsmu::gui {

class TestStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit TestStatusBar(QWidget* parent = nullptr);

    void setProgress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void setRunState(RunState state);

private:
    QLabel* m_time = nullptr;
    QLabel* m_step = nullptr;
    QLabel* m_rate = nullptr;
    QLabel* m_state = nullptr;
};

} // namespace hsmu::gui
