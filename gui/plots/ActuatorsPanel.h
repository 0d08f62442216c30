#pragma once
// ActuatorsPanel: the live views of a multi-actuator specimen (docs/console.md, "Actuators and
// setup"; issue 24 item 6), shown under the console's plots and in the replay window when the
// test has multi-DOF elements (RunLayout::channels):
//   - a selector of every channel group (core/output/ChannelGroups.h): each actuator (command,
//     stroke, force: the tracking of that actuator), each basic DOF (commanded, measured,
//     force), and per element every basic deformation, basic force, actuator stroke and
//     actuator force in one plot (one curve each);
//   - the selected group's time histories (HistoryPlot; channels of the first channel's unit
//     on the left axis, the others, e.g. the force of a displacement channel, on the right;
//     both axes name their unit), and a line with the latest row's values and units;
//   - the sketch of the selected element's setup with its deformed shape (SetupSketchView),
//     for an experimental link2d element.
// Values are StepRecord::channels as the test recorded them (the same numbers as
// /elements/channels and channels.csv). Feeding as LivePlotsPanel: appendRecords() appends,
// refresh() redraws.
// Thread rules: GUI thread only.

#include "core/experiment/StepRecord.h"
#include "core/output/ChannelGroups.h"
#include "core/output/RunLayout.h"
#include "gui/plots/PlotReferences.h"

#include <QWidget>

#include <array>
#include <vector>

class QComboBox;
class QLabel;

namespace hsmu::gui {

class HistoryPlot;
class SetupSketchView;

class ActuatorsPanel : public QWidget {
    Q_OBJECT
public:
    explicit ActuatorsPanel(QWidget* parent = nullptr);

    /// Set up for a run of this layout (clears the data); the sketches come from the
    /// references' link2d specimens. The first actuator group is shown.
    void configure(const RunLayout& layout, const PlotReferences& references);
    /// The layout has multi-DOF element channels (else the panel has nothing to show).
    bool hasChannels() const { return !m_groups.empty(); }
    void appendRecords(const std::vector<StepRecord>& rows);
    void clearData();
    /// Rescale and replot the plot (queued); the sketch repaints itself.
    void refresh();

    /// Show group `index` of groups() (its whole history so far).
    void showGroup(int index);
    int shownGroup() const { return m_group; }
    const std::vector<ChannelGroup>& groups() const { return m_groups; }
    /// The latest row's values of the shown group, in its channel order (empty before a row).
    std::vector<double> shownValues() const;

    QComboBox& selector() const { return *m_selector; }
    HistoryPlot& plot() const { return *m_plot; }
    QLabel& values() const { return *m_values; }
    SetupSketchView& sketch() const { return *m_sketch; }

private:
    void retranslate();
    QString groupTitle(const ChannelGroup& g) const;
    QString curveName(const ElementChannel& c, const ChannelGroup& g) const;
    void showValues();
    void showSketchOf(const std::string& element);
    void feedSketch(const StepRecord& row);

    RunLayout m_layout;
    PlotReferences m_references;
    std::vector<ChannelGroup> m_groups;
    int m_group = -1;
    std::string m_sketchElement;
    std::array<int, 3> m_sketchChannels{-1, -1, -1};
    /// The rows so far, slimmed to step, time and channels, so a newly picked group shows its
    /// whole history.
    std::vector<StepRecord> m_history;
    QComboBox* m_selector = nullptr;
    HistoryPlot* m_plot = nullptr;
    QLabel* m_values = nullptr;
    SetupSketchView* m_sketch = nullptr;
};

} // namespace hsmu::gui
