#pragma once
// TestStatusBar: test time [s], step (of total), steps per second with the time left at that
// rate (m:ss), the run state, the link to
// the specimens per site (SiteHealthLabel: the built-in virtual lab or tcp://host:port, with
// its state read from the test's SiteMonitor, the one source of truth) and the recording
// file, always visible at the bottom of the main window. Temporary messages use
// QStatusBar::showMessage. Thread rules: GUI thread only.

#include "gui/app/RunState.h"
#include "gui/app/SiteHealthLabel.h"

#include <QStatusBar>

#include <memory>

class QLabel;

namespace hsmu::gui {

class TestStatusBar : public QStatusBar {
    Q_OBJECT
public:
    explicit TestStatusBar(QWidget* parent = nullptr);

    void setProgress(int step, int totalSteps, double testTime, double stepsPerSecond);
    void setRunState(RunState state);
    /// Empty: not recording.
    void setRecordingFile(const QString& file);
    /// The loaded test's sites and its monitor (SiteHealthLabel); no sites: "no link".
    void setLink(const QList<SiteHealthLabel::Site>& sites,
                 std::shared_ptr<const SiteMonitor> monitor);
    SiteHealthLabel* link() const { return m_link; }

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
    SiteHealthLabel* m_link = nullptr;
    QLabel* m_recording = nullptr;
};

} // namespace hsmu::gui
