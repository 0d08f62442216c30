#pragma once
// ReplayWindow: re-opens a recorded test (an HDF5 run record, docs/recording.md) and plays it
// through the console's own LivePlotsPanel: play / pause, scrub with the slider, a chosen
// speed (test seconds per wall second); the tool bar shows the test time and the step.
// Playing advances a RecordPlayback on a ~30 Hz timer and replots once per tick, like the
// live console. The ground-motion plot shows the whole recorded acceleration with a cursor.
// open() refuses a bad file (missing, not HDF5, not ours, newer schema, truncated) with the
// RecordReader's message; openWithDialog() asks for a file and shows that message in a box.
// Re-identify... (reidentify()): identify the recorded specimen again offline with the recorded
// or other settings (ReidentifyDialog: method, override JSON; Reidentification.h) on a worker
// thread, the window staying responsive with a busy bar; the re-identified parameter history
// is then overlaid on the parameter plots as "re-identified (METHOD)" for comparison with the
// recorded one; an error goes to a message box (and reidentificationFailed()).
// Panels: every alarm, operator event and note of the record (double-click: jump to its
// step) and the numeric values at the cursor step (ReplayPanels.h). Menus: File (export the
// time window the displacement plot shows as CSV, export the plots as PNG / SVG / PDF,
// Close: Ctrl+W), Playback (Play / Pause: Space, step back / forward: Left / Right, Home,
// End), View (the panels). Every plot has the console's plot tools (PlotTools.h).
// Thread rules: GUI thread only (the identification runs on its own QThread, joined on close).

#include <QElapsedTimer>
#include <QMainWindow>

#include <functional>
#include <memory>
#include <vector>

class QAction;
class QComboBox;
class QLabel;
class QProgressBar;
class QSlider;
class QThread;
class QTimer;

namespace hsmu {
struct RecordData;
struct StepRecord;
} // namespace hsmu

namespace hsmu::gui {

class LivePlotsPanel;
class RecordPlayback;
class ReplayEventList;
class ReplayReadout;

class ReplayWindow : public QMainWindow {
    Q_OBJECT
public:
    static constexpr int kTickMs = 33; ///< ~30 Hz

    /// A window on the record at path, or nullptr with the reason in *error (never throws).
    static ReplayWindow* open(const QString& path, QWidget* parent, QString* error);
    /// open() with the file read on a worker thread while a modal busy dialog (Qt's own
    /// Cancel button) keeps the GUI responsive; RecordReader fails a damaged file within 5 s.
    /// nullptr with error set on failure; nullptr with error empty when cancelled (the worker
    /// then finishes on its own and its result is dropped).
    static ReplayWindow* openInBackground(const QString& path, QWidget* parent, QString* error);
    /// File dialog, then openInBackground() and show (deleted on close); a bad file: an error
    /// box.
    static ReplayWindow* openWithDialog(QWidget* parent);

    ~ReplayWindow() override;

    LivePlotsPanel& panel() const { return *m_panel; }
    const RecordPlayback& playback() const { return *m_playback; }
    int rowsShown() const;
    int rowCount() const;
    bool isPlaying() const;
    bool isReidentifying() const { return m_reidentifier != nullptr; }
    ReplayEventList& events() const { return *m_events; }
    ReplayReadout& readout() const { return *m_readout; }
    /// The rows inside the time window the displacement plot shows, as CSV (ReplayExport).
    bool exportWindowCsv(const QString& path, QString* error = nullptr, int* rows = nullptr) const;
    /// The overlay curve name of a re-identification by method ("UKF" / "Nelder-Mead").
    static QString reidentifiedCurveName(const QString& method);

public slots:
    void play();
    void pause();
    /// Show exactly n rows (0 .. rowCount()); pauses nothing.
    void seek(int n);
    /// Test seconds per wall second (> 0).
    void setSpeed(double factor);
    /// Re-identify off the GUI thread: method "ukf" / "nelderMead" ("" the recorded one),
    /// overridePath a JSON file or "". Ignored while one runs.
    void reidentify(const QString& method, const QString& overridePath);
    /// ReidentifyDialog, then reidentify().
    void reidentifyWithDialog();

signals:
    /// After every change of the rows shown.
    void positionChanged(int rowsShown);
    /// The last row is shown (play stops).
    void finished();
    /// The re-identified history was overlaid as curveName.
    void reidentified(const QString& curveName);
    void reidentificationFailed(const QString& error);

private:
    ReplayWindow(std::shared_ptr<const RecordData> data, const QString& path, QWidget* parent);
    void tick();
    void showRows(const std::vector<StepRecord>& rows, bool restart);
    void updateControls();
    void buildPanelsAndMenus();
    void showReidentification();

    /// Set a text now and again at each language change (tr() inside `texts`).
    void live(std::function<void()> texts);

    std::vector<std::function<void()>> m_texts; ///< every live() text, in order
    std::unique_ptr<RecordPlayback> m_playback;
    LivePlotsPanel* m_panel = nullptr;
    ReplayEventList* m_events = nullptr;
    ReplayReadout* m_readout = nullptr;
    QAction* m_playAction = nullptr;
    QComboBox* m_speed = nullptr;
    QSlider* m_slider = nullptr;
    QLabel* m_position = nullptr;
    QTimer* m_timer = nullptr;
    QElapsedTimer m_wall; ///< since the last tick while playing
    QString m_path;
    QAction* m_reidentifyAction = nullptr;
    QProgressBar* m_busy = nullptr;
    QAction* m_busyAction = nullptr; ///< shows / hides m_busy in the tool bar
    QThread* m_reidentifier = nullptr;
    struct Outcome;
    std::shared_ptr<Outcome> m_outcome; ///< written by m_reidentifier, read after it finished
};

} // namespace hsmu::gui
