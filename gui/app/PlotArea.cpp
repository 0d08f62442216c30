#include "gui/app/PlotArea.h"

#include "gui/plots/HistoryPlot.h"
#include "gui/plots/HysteresisPlot.h"

#include <QHBoxLayout>
#include <QSplitter>

namespace hsmu::gui {

PlotArea::PlotArea(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("plotArea"));
    auto* splitter = new QSplitter(Qt::Horizontal, this);
    m_hysteresis = new HysteresisPlot(splitter);
    m_history = new HistoryPlot(splitter);
    splitter->addWidget(m_hysteresis);
    splitter->addWidget(m_history);
    splitter->setStretchFactor(0, 1);
    splitter->setStretchFactor(1, 1);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(splitter);
}

void PlotArea::showTest(const RunLayout& layout) {
    m_hysteresis->showElements(layout, HysteresisPlot::specimenWithTwins(layout));
    m_history->showDisplacements(layout);
}

void PlotArea::appendRecords(const std::vector<StepRecord>& rows) {
    m_hysteresis->appendRecords(rows);
    m_history->appendRecords(rows);
    m_hysteresis->refresh();
    m_history->refresh();
}

} // namespace hsmu::gui
