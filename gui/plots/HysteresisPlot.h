#pragma once
// HysteresisPlot: force against deformation of chosen elements, as parametric curves (the
// loop is not a function of deformation). The first element is drawn as the reference (for a
// specimen: its *measured* loop), the others are overlaid (e.g. its numerical twins).
// Axis labels carry the element units (RunLayout). Used live by the console and offscreen by
// `hsmu run --plots`; with setAxes() / addCurve() also for precomputed loops (`hsmu compare
// --plots`: reference, initial and updated runs of one element overlaid).
// Thread rules: GUI thread only, like every widget.

#include "core/output/RunLayout.h"
#include "core/experiment/StepRecord.h"

#include <qcustomplot.h>

#include <functional>
#include <vector>

namespace hsmu::gui {

class HysteresisPlot : public QCustomPlot {
    Q_OBJECT
public:
    explicit HysteresisPlot(QWidget* parent = nullptr);

    /// The element shown by default: the specimen the updating identifies, else the first
    /// experimental element, else the first nonlinear one; -1 if none.
    static int defaultElement(const RunLayout& layout);
    /// The elements that have a loop to show (experimental or nonlinear), in layout order.
    static std::vector<int> loopElements(const RunLayout& layout);
    /// `element` followed, for a specimen, by the numerical nonlinear elements of its type (a
    /// spread few). Empty if element < 0.
    static std::vector<int> withTwins(const RunLayout& layout, int element);
    /// withTwins(layout, defaultElement(layout)).
    static std::vector<int> specimenWithTwins(const RunLayout& layout);

    /// Replace the curves by one per element index in `elements` (indices into layout).
    void showElements(const RunLayout& layout, const std::vector<int>& elements);
    /// Overlay the auxiliary model (docs/method.md, The four modules): its force
    /// (StepRecord::updating.auxiliaryForce) against the specimen's measured deformation.
    /// When the updating identifies a link2d specimen's basic DOF (UpdatingInfo::basicDof),
    /// the specimen's curve and the overlay are that DOF's channels (StepRecord::channels).
    /// Nothing if layout has no updating or its specimen is unknown. Call after showElements().
    void addAuxiliaryModel(const RunLayout& layout);
    /// Title and axis labels for loops in these units ("rad" labels rotation and moment).
    void setAxes(const QString& title, const QString& deformationUnit, const QString& forceUnit);
    /// Add a curve of precomputed points (not fed by appendRecords(); removed by the next
    /// showElements()). Its pen is the next series colour.
    void addCurve(const QString& name, const QVector<double>& deformation,
                  const QVector<double>& force);
    /// Append one point per curve per record.
    void appendRecords(const std::vector<StepRecord>& records);
    /// Remove every point, keep the curves.
    void clearData();
    /// Rescale to the data (with a margin) and replot (queued: at most once per frame).
    void refresh();
    /// The texts of showElements() / addAuxiliaryModel() again in the current language (also
    /// done on each QEvent::LanguageChange), the curves' data untouched.
    void retranslate();

private:
    std::vector<std::function<void()>> m_texts; ///< tr() texts of the shown elements
    struct Series {
        int element = 0;
        QCPCurve* curve = nullptr;
        bool auxiliary = false; ///< force from StepRecord::updating.auxiliaryForce
        /// StepRecord::channels of the deformation and force shown (-1: the element's own)
        int deformationChannel = -1, forceChannel = -1;
    };
    std::vector<Series> m_series;
};

} // namespace hsmu::gui
