#pragma once
// ParameterPlot: the history of one identified parameter with its uncertainty, like the
// paper's Figure 10: the estimate theta(t) as a line, the band theta ± kBandSigmas sigma(t)
// shaded, and optionally the true value (the virtual specimen's own parameter) as a dashed
// line, and optionally the identification bounds as two red dotted lines (kept in range).
// Values in the law's own units (normalized by uRef / fRef for Bouc-Wen).
// Two feeds: StepRecords (the console: parameter `index` of StepRecord::updating) or
// precomputed samples (hsmu compare). Overlays: further named curves over the same axes (e.g.
// a re-identified history in the replay window), each in its own palette colour, in the
// legend; they survive clearData() and go with showParameter().
// Thread rules: GUI thread only, like every widget.

#include "core/experiment/StepRecord.h"

#include <qcustomplot.h>

#include <vector>

namespace hsmu::gui {

class ParameterPlot : public QCustomPlot {
    Q_OBJECT
public:
    static constexpr double kBandSigmas = 2.0;

    explicit ParameterPlot(QWidget* parent = nullptr);

    /// Show parameter `name`, which is entry `index` of StepRecord::updating.parameters and
    /// .stddev; clears the data and the true value.
    void showParameter(const QString& name, int index = 0);
    const QString& parameterName() const { return m_name; }
    /// Draw the true value as a dashed line over the data's time span; NaN hides it.
    void setTrueValue(double value);
    /// Draw the lower and upper bounds of the identification (infinite or NaN: not drawn).
    /// Returns whether they changed (the caller redraws).
    bool setBounds(double lower, double upper);

    /// The estimate and the band's edges (value ∓ kBandSigmas sigma), e.g. for tests.
    const QCPGraph* estimateGraph() const { return m_value; }
    const QCPGraph* lowerBandGraph() const { return m_lower; }
    const QCPGraph* upperBandGraph() const { return m_upper; }
    const QCPItemStraightLine* lowerBoundLine() const { return m_lowerBound; }
    const QCPItemStraightLine* upperBoundLine() const { return m_upperBound; }

    /// Append one point per record that carries updating data.
    void appendRecords(const std::vector<StepRecord>& records);
    /// Append samples: time [s], estimate and standard deviation (equal lengths).
    void appendSamples(const QVector<double>& time, const QVector<double>& value,
                       const QVector<double>& sigma);
    void clearData();
    /// Show the curve `name` (time [s], values; equal lengths), replacing one of that name.
    void setOverlay(const QString& name, const QVector<double>& time, const QVector<double>& values);
    /// The overlay curve called name, or nullptr.
    const QCPGraph* overlayGraph(const QString& name) const;
    /// Rescale to the data (with a margin) and replot (queued).
    void refresh();

private:
    void updateTrueLine();

    int m_index = 0;
    QString m_name;
    std::vector<QCPGraph*> m_overlays;
    double m_trueValue = qQNaN();
    QCPGraph* m_value = nullptr;
    QCPGraph* m_upper = nullptr;
    QCPGraph* m_lower = nullptr;
    QCPGraph* m_true = nullptr;
    QCPItemStraightLine* m_lowerBound = nullptr;
    QCPItemStraightLine* m_upperBound = nullptr;
    double m_boundLow = qQNaN();
    double m_boundHigh = qQNaN();
};

} // namespace hsmu::gui
