#include "gui/plots/ActuatorsPanel.h"

#include "gui/app/LiveText.h"
#include "gui/plots/HistoryPlot.h"
#include "gui/plots/PlotTools.h"
#include "gui/plots/SetupSketchView.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

namespace hsmu::gui {

namespace {

// What an axis of this unit shows.
QString axisLabel(const QString& unit) {
    if (unit == QLatin1String("m"))
        return ActuatorsPanel::tr("Displacement [%1]").arg(unit);
    if (unit == QLatin1String("rad"))
        return ActuatorsPanel::tr("Rotation [%1]").arg(unit);
    if (unit == QLatin1String("kN"))
        return ActuatorsPanel::tr("Force [%1]").arg(unit);
    if (unit == QLatin1String("kN m"))
        return ActuatorsPanel::tr("Moment [%1]").arg(unit);
    return QStringLiteral("[%1]").arg(unit);
}

// core's basic DOF names and channel roles (ElementChannels.h), translated.
QString word(const std::string& w) {
    if (w == "axial")
        return ActuatorsPanel::tr("axial");
    if (w == "shear")
        return ActuatorsPanel::tr("shear");
    if (w == "rotation")
        return ActuatorsPanel::tr("rotation");
    if (w == "commanded")
        return ActuatorsPanel::tr("commanded");
    if (w == "deformation")
        return ActuatorsPanel::tr("measured");
    if (w == "command")
        return ActuatorsPanel::tr("command");
    if (w == "stroke")
        return ActuatorsPanel::tr("stroke");
    if (w == "force")
        return ActuatorsPanel::tr("force");
    return QString::fromStdString(w); // a configured name
}

// "lateral" of "lateral stroke": the channel's subject when the group gathers several.
std::string headOf(const std::string& name) {
    const auto space = name.rfind(' ');
    return space == std::string::npos ? name : name.substr(0, space);
}

StepRecord slim(const StepRecord& r) {
    StepRecord s;
    s.step = r.step;
    s.time = r.time;
    s.channels = r.channels;
    return s;
}

} // namespace

ActuatorsPanel::ActuatorsPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("actuatorsPanel"));
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    row->setSpacing(4);
    auto* left = new QWidget(this);
    auto* column = new QVBoxLayout(left);
    column->setContentsMargins(0, 0, 0, 0);
    column->setSpacing(1);
    m_selector = new QComboBox(left);
    m_selector->setObjectName(QStringLiteral("channelGroup"));
    m_selector->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_selector->setMinimumContentsLength(12);
    m_plot = new HistoryPlot(left);
    m_plot->setObjectName(QStringLiteral("channelPlot"));
    m_plot->setMinimumSize(160, 110);
    m_values = new QLabel(left);
    m_values->setObjectName(QStringLiteral("channelValues"));
    m_values->setWordWrap(true);
    m_values->setTextInteractionFlags(Qt::TextSelectableByMouse);
    column->addWidget(m_selector);
    column->addWidget(m_plot, 1);
    column->addWidget(m_values);
    m_sketch = new SetupSketchView(this);
    row->addWidget(left, 3);
    row->addWidget(m_sketch, 2);
    connect(m_selector, &QComboBox::activated, this, [this](int i) { showGroup(i); });
    LiveText::bind(this, [this] { retranslate(); });
}

void ActuatorsPanel::configure(const RunLayout& layout, const PlotReferences& references) {
    m_layout = layout;
    m_references = references;
    m_groups = channelGroups(layout.channels);
    m_history.clear();
    m_group = -1;
    m_sketchElement.clear();
    int first = 0; // the first actuator's tracking, else the first group
    for (int i = int(m_groups.size()) - 1; i >= 0; --i)
        if (m_groups[std::size_t(i)].kind == ChannelGroupKind::Actuator)
            first = i;
    retranslate();
    if (!m_groups.empty())
        showGroup(first);
    else {
        m_plot->setChannels(QString(), QString(), {});
        m_sketch->clear();
        m_values->clear();
    }
}

QString ActuatorsPanel::groupTitle(const ChannelGroup& g) const {
    const QString e = QString::fromStdString(g.element);
    switch (g.kind) {
    case ChannelGroupKind::BasicDof:
        return tr("%1: %2 DOF").arg(e, word(g.subject));
    case ChannelGroupKind::Actuator:
        return tr("%1: actuator '%2'").arg(e, QString::fromStdString(g.subject));
    case ChannelGroupKind::Deformations:
        return tr("%1: every basic deformation").arg(e);
    case ChannelGroupKind::Forces:
        return tr("%1: every basic force").arg(e);
    case ChannelGroupKind::Strokes:
        return tr("%1: every actuator's stroke").arg(e);
    case ChannelGroupKind::ActuatorForces:
        return tr("%1: every actuator's force").arg(e);
    }
    return e;
}

QString ActuatorsPanel::curveName(const ElementChannel& c, const ChannelGroup& g) const {
    if (!g.subject.empty())
        return word(channelRole(c, g));
    return word(headOf(c.name)); // the DOF or actuator the curve belongs to
}

void ActuatorsPanel::retranslate() {
    const int shown = m_group;
    m_selector->clear();
    for (const ChannelGroup& g : m_groups)
        m_selector->addItem(groupTitle(g));
    m_selector->setToolTip(tr("The actuator, basic DOF or set of channels the plot shows"));
    if (shown >= 0) {
        m_group = -1;
        showGroup(shown);
    }
}

void ActuatorsPanel::showGroup(int index) {
    if (index < 0 || index >= int(m_groups.size()))
        return;
    const bool same = index == m_group;
    m_group = index;
    m_selector->setCurrentIndex(index);
    const ChannelGroup& g = m_groups[std::size_t(index)];
    const QString leftUnit =
        QString::fromStdString(m_layout.channels[std::size_t(g.channels.front())].unit);
    QString rightUnit;
    std::vector<HistoryPlot::Channel> channels;
    for (const int c : g.channels) {
        const ElementChannel& ch = m_layout.channels[std::size_t(c)];
        const QString unit = QString::fromStdString(ch.unit);
        const bool right = unit != leftUnit;
        if (right)
            rightUnit = unit;
        channels.push_back({curveName(ch, g),
                            [c](const StepRecord& r) {
                                return std::size_t(c) < r.channels.size()
                                           ? r.channels[std::size_t(c)]
                                           : qQNaN();
                            },
                            right});
    }
    m_plot->setChannels(groupTitle(g), axisLabel(leftUnit), std::move(channels),
                        rightUnit.isEmpty() ? QString() : axisLabel(rightUnit));
    m_plot->appendRecords(m_history);
    if (!same)
        PlotTools::attach(*m_plot)->setAutoscale(true);
    m_plot->refresh();
    showSketchOf(g.element);
    showValues();
}

void ActuatorsPanel::showSketchOf(const std::string& element) {
    if (element == m_sketchElement)
        return;
    m_sketchElement = element;
    m_sketchChannels = basicDeformationChannels(m_layout.channels, element);
    bool found = false;
    for (const auto& [name, spec] : m_references.link2dSpecimens)
        if (name == element) {
            m_sketch->setSpecimen(name, spec);
            found = true;
        }
    m_sketch->setVisible(found);
    if (!found)
        m_sketch->clear();
    for (const StepRecord& r : m_history) // its largest displacement so far sets the scale
        feedSketch(r);
}

void ActuatorsPanel::feedSketch(const StepRecord& row) {
    Eigen::Vector3d d;
    for (int k = 0; k < 3; ++k) {
        const int c = m_sketchChannels[std::size_t(k)];
        d(k) = c >= 0 && std::size_t(c) < row.channels.size() ? row.channels[std::size_t(c)] : 0.0;
    }
    m_sketch->setDeformation(d);
}

std::vector<double> ActuatorsPanel::shownValues() const {
    std::vector<double> out;
    if (m_history.empty() || m_group < 0)
        return out;
    const StepRecord& last = m_history.back();
    for (const int c : m_groups[std::size_t(m_group)].channels)
        out.push_back(std::size_t(c) < last.channels.size() ? last.channels[std::size_t(c)]
                                                            : qQNaN());
    return out;
}

void ActuatorsPanel::showValues() {
    const std::vector<double> v = shownValues();
    if (v.empty()) {
        m_values->setText(tr("No step yet."));
        return;
    }
    const ChannelGroup& g = m_groups[std::size_t(m_group)];
    QStringList parts;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const ElementChannel& ch = m_layout.channels[std::size_t(g.channels[i])];
        parts << QStringLiteral("%1 %2 %3")
                     .arg(curveName(ch, g), QString::number(v[i], 'g', 6),
                          QString::fromStdString(ch.unit));
    }
    m_values->setText(tr("Step %1, t = %2 s: %3")
                          .arg(m_history.back().step)
                          .arg(m_history.back().time, 0, 'f', 3)
                          .arg(parts.join(QStringLiteral(", "))));
}

void ActuatorsPanel::appendRecords(const std::vector<StepRecord>& rows) {
    if (m_groups.empty() || rows.empty())
        return;
    for (const StepRecord& r : rows) {
        m_history.push_back(slim(r));
        if (!m_sketchElement.empty())
            feedSketch(r);
    }
    m_plot->appendRecords(rows);
    showValues();
}

void ActuatorsPanel::clearData() {
    m_history.clear();
    m_plot->clearData();
    m_sketch->reset();
    showValues();
}

void ActuatorsPanel::refresh() {
    if (!m_groups.empty())
        m_plot->refresh();
}

} // namespace hsmu::gui
