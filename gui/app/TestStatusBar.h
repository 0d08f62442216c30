#pragma once
// TestStatusBar: test time [s], step (of total), steps per second, the run state, the link to
// the specimens (built-in virtual lab or tcp://host:port, with its state) and the recording
// file, always visible at the bottom of the main window. Temporary messages use
// QStatusBar::showMessage. Thread rules: GUI thread only.

#include "gui/app/RunState.h"

#include <QStatusBar>

#include <memory>

class QLabel;

namespace hsmu {
class SiteMonitor;
}

namespace hsmu::gui {

class SiteHealthLabel;

class TestStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit TestStatusBar(QWidget* parent = nullptr);

    void setProgress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void setRunState(RunState state);
    /// ok = false shows the link in the alarm colour (e.g. a link fault).
    void setLink(const QString& text, bool ok);
    /// Empty: not recording.
    void setRecordingFile(const QString& file);
    /// Per-site health of the loaded test (SiteHealthLabel); nullptr hides it.
    void setSites(std::shared_ptr<const SiteMonitor> monitor);

private:
    struct Progress {
        int step = 0, total = 0;
        double time = 0.0, rate = 0.0;
    } m_progress;
    RunState m_runState = RunState::Idle;
    QString m_recordingFile;
    QLabel* m_time = nullptr;
    QLabel* m_step = nullptr;
    QLabel* m_rate = nullptr;
    QLabel* m_state = nullptr;
    QLabel* m_link = nullptr;
    QLabel* m_recording = nullptr;
    SiteHealthLabel* m_sites = nullptr;
};

} // namespace hsmu::gui
