#pragma once
// PlotArea: the main window's central widget: the live plots of a test (the specimen's
// measured hysteresis with its numerical twins, the DOF displacement histories). MainWindow
// only calls showTest() when a test is loaded and appendRecords() with each ~30 Hz batch;
// what is drawn (and how many plots) is this class's business alone.
// Thread rules: GUI thread only.

#include "core/output/RunLayout.h"
#include "core/test/StepRecord.h"

#include <QWidget>

#include <vector>

namespace hsmu::gui {

class HistoryPlot;
class HysteresisPlot;

class PlotArea : public QWidget {
    Q_OBJECT
public:
    explicit PlotArea(QWidget* parent = nullptr);

    /// A new test: clear, label axes and curves from its layout.
    void showTest(const RunLayout& layout);
    /// Append a batch of rows (oldest first) and replot once.
    void appendRecords(const std::vector<StepRecord>& rows);

private:
    HysteresisPlot* m_hysteresis = nullptr;
    HistoryPlot* m_history = nullptr;
};

} // namespace hsmu::gui
