#pragma once
// ReplayWindow: re-opens a recorded test (an HDF5 run record, docs/recording.md) and plays it
// through the console's own LivePlotsPanel: play / pause, scrub with the slider, a chosen
// speed (test seconds per wall second); the tool bar shows the test time and the step.
// Playing advances a RecordPlayback on a ~30 Hz timer and replots once per tick, like the
// live console. The ground-motion plot shows the whole recorded acceleration with a cursor.
// open() refuses a bad file (missing, not HDF5, not ours, newer schema, truncated) with the
// RecordReader's message; openWithDialog() asks for a file and shows that message in a box.
// Thread rules: GUI thread only.

#include <QElapsedTimer>
#include <QMainWindow>

#include <memory>
#include <vector>

class QAction;
class QComboBox;
class QLabel;
class QSlider;
class QTimer;

namespace hsmu {
struct RecordData;
struct StepRecord;
} // namespace hsmu

namespace hsmu::gui {

class LivePlotsPanel;
class RecordPlayback;

class ReplayWindow : public QMainWindow {
    Q_OBJECT
public:
    static constexpr int kTickMs = 33; ///< ~30 Hz

    /// A window on the record at path, or nullptr with the reason in *error (never throws).
    static ReplayWindow* open(const QString& path, QWidget* parent, QString* error);
    /// File dialog, then open() and show (deleted on close); a bad file: an error box.
    static ReplayWindow* openWithDialog(QWidget* parent);

    ~ReplayWindow() override;

    LivePlotsPanel& panel() const { return *m_panel; }
    const RecordPlayback& playback() const { return *m_playback; }
    int rowsShown() const;
    int rowCount() const;
    bool isPlaying() const;

public slots:
    void play();
    void pause();
    /// Show exactly n rows (0 .. rowCount()); pauses nothing.
    void seek(int n);
    /// Test seconds per wall second (> 0).
    void setSpeed(double factor);

signals:
    /// After every change of the rows shown.
    void positionChanged(int rowsShown);
    /// The last row is shown (play stops).
    void finished();

private:
    ReplayWindow(std::shared_ptr<const RecordData> data, const QString& path, QWidget* parent);
    void tick();
    void showRows(const std::vector<StepRecord>& rows, bool restart);
    void updateControls();

    std::unique_ptr<RecordPlayback> m_playback;
    LivePlotsPanel* m_panel = nullptr;
    QAction* m_playAction = nullptr;
    QComboBox* m_speed = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_position = nullptr;
    QTimer* m_timer = nullptr;
    QElapsedTimer m_wall; ///< since the last tick while playing
};

} // namespace hsmu::gui
