#include "gui/plots/HysteresisPlot.h"

#include "gui/app/LiveText.h"
#include "gui/plots/PlotSelection.h"
#include "gui/plots/PlotStyle.h"

#include <algorithm>

namespace hsmu::gui {

HysteresisPlot::HysteresisPlot(QWidget* parent) : QCustomPlot(parent) {
    PlotStyle::apply(*this);
    xAxis->ticker()->setTickCount(3); // rotations print long (-0.0005, "0,0010,0015" ran together)
    LiveText::bind(this, [this] { retranslate(); });
}

void HysteresisPlot::retranslate() {
    if (m_texts.empty()) { // no element (no test loaded): no quantity without its unit
        xAxis->setLabel(QString());
        yAxis->setLabel(QString());
    }
    for (const auto& texts : m_texts)
        texts();
    replot(QCustomPlot::rpQueuedReplot);
}

int HysteresisPlot::defaultElement(const RunLayout& layout) {
    // The identified specimen first: its loop is the one the auxiliary model and the
    // Parameters dock describe (two labs: Bearing D, not the first specimen, Bearing C).
    for (std::size_t i = 0; i < layout.elements.size() && layout.updating; ++i)
        if (layout.elements[i].experimental && layout.elements[i].name == layout.updating->specimen)
            return int(i);
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].experimental)
            return int(i);
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].nonlinear)
            return int(i);
    return -1;
}

std::vector<int> HysteresisPlot::loopElements(const RunLayout& layout) {
    std::vector<int> out;
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (layout.elements[i].experimental || layout.elements[i].nonlinear)
            out.push_back(int(i));
    return out;
}

std::vector<int> HysteresisPlot::withTwins(const RunLayout& layout, int element) {
    if (element < 0 || std::size_t(element) >= layout.elements.size())
        return {};
    const ElementInfo& shown = layout.elements[std::size_t(element)];
    std::vector<int> twins;
    for (std::size_t i = 0; i < layout.elements.size() && shown.experimental; ++i) {
        const ElementInfo& e = layout.elements[i];
        if (int(i) != element && e.nonlinear && !e.experimental && e.type == shown.type)
            twins.push_back(int(i));
    }
    std::vector<int> out{element};
    for (int i : spreadSubset(twins, kMaxPlottedElements - 1)) // many twins: a spread few
        out.push_back(i);
    return out;
}

std::vector<int> HysteresisPlot::specimenWithTwins(const RunLayout& layout) {
    return withTwins(layout, defaultElement(layout));
}

void HysteresisPlot::showElements(const RunLayout& layout, const std::vector<int>& elements) {
    clearPlottables();
    m_series.clear();
    m_texts.clear();
    for (std::size_t k = 0; k < elements.size(); ++k) {
        const ElementInfo& e = layout.elements[std::size_t(elements[k])];
        auto* curve = new QCPCurve(xAxis, yAxis);
        const QString name = QString::fromStdString(e.name);
        const bool experimental = e.experimental;
        m_texts.push_back([this, curve, name, experimental] {
            curve->setName(experimental ? tr("%1 (specimen, measured)").arg(name)
                                        : tr("%1 (numerical)").arg(name));
        });
        curve->setPen(PlotStyle::seriesPen(int(k)));
        curve->setAntialiased(false); // thousands of segments per live redraw
        m_series.push_back({elements[k], curve, false});
    }
    if (!elements.empty()) {
        const ElementInfo& first = layout.elements[std::size_t(elements.front())];
        const QString name = QString::fromStdString(first.name);
        const QString deformation = QString::fromStdString(first.units.deformation);
        const QString force = QString::fromStdString(first.units.force);
        // Named after the element shown first (its twins are named in the legend).
        m_texts.push_back([this, name, deformation, force] {
            setAxes(tr("Hysteresis of %1").arg(name), deformation, force);
        });
    }
    retranslate();
    legend->setVisible(!m_series.empty());
    replot();
}

void HysteresisPlot::addAuxiliaryModel(const RunLayout& layout) {
    if (!layout.updating)
        return;
    // A link2d's identified basic DOF: its channels, for the specimen's curve and the overlay.
    const UpdatingInfo& u = *layout.updating;
    int deformationChannel = -1, forceChannel = -1;
    for (std::size_t c = 0; c < layout.channels.size() && !u.basicDof.empty(); ++c) {
        if (layout.channels[c].element != u.specimen)
            continue;
        if (layout.channels[c].name == u.basicDof + " deformation")
            deformationChannel = int(c);
        if (layout.channels[c].name == u.basicDof + " force")
            forceChannel = int(c);
    }
    for (std::size_t i = 0; i < layout.elements.size(); ++i) {
        if (layout.elements[i].name != u.specimen)
            continue;
        if (deformationChannel >= 0 && forceChannel >= 0) {
            for (Series& s : m_series) {
                if (s.element != int(i))
                    continue;
                s.deformationChannel = deformationChannel;
                s.forceChannel = forceChannel;
                const QString name = QString::fromStdString(u.specimen + " " + u.basicDof);
                QCPCurve* curve = s.curve;
                m_texts.push_back([this, curve, name] {
                    curve->setName(tr("%1 (specimen, measured)").arg(name));
                });
            }
            const QString name = QString::fromStdString(u.specimen + " " + u.basicDof);
            const QString deformation = QString::fromStdString(u.units.deformation);
            const QString force = QString::fromStdString(u.units.force);
            m_texts.push_back([this, name, deformation, force] {
                setAxes(tr("Hysteresis of %1").arg(name), deformation, force);
            });
        }
        auto* curve = new QCPCurve(xAxis, yAxis);
        const QString method = QString::fromStdString(layout.updating->method);
        m_texts.push_back(
            [this, curve, method] { curve->setName(tr("auxiliary model (%1)").arg(method)); });
        m_texts.back()();
        QPen pen = PlotStyle::seriesPen(int(m_series.size()));
        pen.setStyle(Qt::DashLine);
        curve->setPen(pen);
        curve->setAntialiased(false);
        m_series.push_back({int(i), curve, true, deformationChannel, -1});
        legend->setVisible(true);
        if (deformationChannel >= 0)
            retranslate(); // the specimen's curve and the axes: the identified DOF's
        return;
    }
}

void HysteresisPlot::setAxes(const QString& title, const QString& deformationUnit,
                             const QString& forceUnit) {
    const bool rotational = deformationUnit == QLatin1String("rad");
    xAxis->setLabel(rotational ? tr("Rotation [%1]").arg(deformationUnit)
                               : tr("Deformation [%1]").arg(deformationUnit));
    yAxis->setLabel(rotational ? tr("Moment [%1]").arg(forceUnit)
                               : tr("Force [%1]").arg(forceUnit));
    PlotStyle::setTitle(*this, title);
}

void HysteresisPlot::addCurve(const QString& name, const QVector<double>& deformation,
                              const QVector<double>& force) {
    const int index = plottableCount();
    auto* curve = new QCPCurve(xAxis, yAxis);
    curve->setName(name);
    curve->setPen(PlotStyle::seriesPen(index));
    QVector<double> t(std::min(deformation.size(), force.size()));
    for (qsizetype i = 0; i < t.size(); ++i)
        t[i] = double(i);
    curve->setData(t, deformation.mid(0, t.size()), force.mid(0, t.size()));
    legend->setVisible(true);
}

void HysteresisPlot::appendRecords(const std::vector<StepRecord>& records) {
    for (const Series& s : m_series) {
        QVector<double> t, x, y;
        t.reserve(qsizetype(records.size()));
        x.reserve(qsizetype(records.size()));
        y.reserve(qsizetype(records.size()));
        for (const StepRecord& r : records) {
            if (std::size_t(s.element) >= r.elements.size() || (s.auxiliary && !r.hasUpdating))
                continue;
            if (std::max(s.deformationChannel, s.forceChannel) >= int(r.channels.size()))
                continue; // a record without the channels (they are drawn live)
            const ElementSample& e = r.elements[std::size_t(s.element)];
            t.push_back(r.time);
            x.push_back(s.deformationChannel >= 0 ? r.channels[std::size_t(s.deformationChannel)]
                                                  : e.deformation);
            y.push_back(s.auxiliary          ? r.updating.auxiliaryForce
                        : s.forceChannel >= 0 ? r.channels[std::size_t(s.forceChannel)]
                                              : e.force);
        }
        s.curve->addData(t, x, y, true);
    }
}

void HysteresisPlot::clearData() {
    for (const Series& s : m_series)
        s.curve->data()->clear();
}

void HysteresisPlot::refresh() {
    PlotStyle::rescaleWithMargin(*this);
    replot(QCustomPlot::rpQueuedReplot);
}

} // namespace hsmu::gui
