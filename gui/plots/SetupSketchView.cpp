#include "gui/plots/SetupSketchView.h"

#include "core/config/Link2dConfig.h"
#include "gui/app/AlarmText.h"

#include <QEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace hsmu::gui {

namespace {

constexpr int kMargin = 14;  // [px] around the drawing
constexpr int kCaption = 34; // [px] the caption's two rows

QColor colourOf(SketchPart part) {
    switch (part) {
    case SketchPart::Element:
    case SketchPart::Rotation:
        return QColor(0x1f, 0x77, 0xb4);
    case SketchPart::Platform:
        return QColor(0x55, 0x55, 0x55);
    case SketchPart::Actuator:
        return QColor(0xe6, 0x6c, 0x00);
    }
    return Qt::black;
}

} // namespace

SetupSketchView::SetupSketchView(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("setupSketch"));
    setMinimumSize(160, 110);
    setAutoFillBackground(true);
    QPalette p = palette();
    p.setColor(QPalette::Window, Qt::white);
    setPalette(p);
}

SetupSketchView::~SetupSketchView() = default;

void SetupSketchView::setSpecimen(const std::string& name, const Link2dSpec& spec) {
    m_name = name;
    m_geometry = {};
    m_geometry.dofs = spec.dofs;
    m_geometry.length = spec.length;
    m_geometry.angleDeg = spec.angle;
    std::string error;
    m_setup = buildLink2dSetup(spec, error);
    m_problem = m_setup ? QString() : AlarmText::reason(QString::fromStdString(error));
    m_actuatorNames.clear();
    for (const ActuatorSpec& a : spec.actuators)
        m_actuatorNames << QString::fromStdString(a.channel.name);
    reset();
}

void SetupSketchView::clear() {
    m_name.clear();
    m_setup.reset();
    m_problem.clear();
    m_actuatorNames.clear();
    reset();
}

void SetupSketchView::reset() {
    m_d.setZero();
    m_peak = 0.0;
    recompute();
}

void SetupSketchView::setDeformation(const Eigen::Vector3d& d) {
    if (!d.allFinite())
        return;
    m_d = d;
    m_peak = std::max({m_peak, std::abs(d(0)), std::abs(d(1)), m_geometry.length * std::abs(d(2))});
    recompute();
}

void SetupSketchView::recompute() {
    m_rest = m_deformed = SetupSketch{};
    if (m_setup) {
        m_rest = setupSketch(*m_setup, m_geometry, Eigen::Vector3d::Zero(), 0.0);
        m_deformed = setupSketch(*m_setup, m_geometry, m_d, sketchScale(m_peak, m_geometry.length));
    }
    update();
}

QString SetupSketchView::caption() const {
    if (m_name.empty())
        return QString();
    const QString name = QString::fromStdString(m_name);
    if (!m_problem.isEmpty())
        return QStringLiteral("%1: %2").arg(name, m_problem);
    if (m_setup && !m_deformed.drawable)
        return tr("%1: no 2-D drawing of its setup %2 (a 3-D or aggregated setup); its "
                  "actuators are in the plot.")
            .arg(name, QString::fromStdString(m_setup->typeName()));
    // two rows: the element and its setup, then the scale (never cut off by a long name)
    return QStringLiteral("%1 (%2)\n%3")
        .arg(name, QString::fromStdString(m_setup->typeName()),
             tr("deformed shape x%1 (solid), at rest (dashed)").arg(m_deformed.scale));
}

void SetupSketchView::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange)
        update();
    QWidget::changeEvent(event);
}

void SetupSketchView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    p.setPen(Qt::black);
    if (!m_deformed.drawable) { // a reason, wrapped to the view
        p.drawText(rect().adjusted(4, 2, -4, -2), Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap,
                   caption());
        return;
    }
    const QStringList rows = caption().split(QLatin1Char('\n'));
    const int rowHeight = kCaption / 2;
    for (int r = 0; r < rows.size() && r < 2; ++r)
        p.drawText(QRect(4, 1 + r * rowHeight, width() - 8, rowHeight),
                   Qt::AlignLeft | Qt::AlignVCenter | Qt::TextSingleLine,
                   fontMetrics().elidedText(rows[r], Qt::ElideMiddle, width() - 8));
    // One metres-to-pixels scale for x and y (the drawing keeps its proportions), y up.
    double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
    for (const SetupSketch* s : {&m_rest, &m_deformed})
        for (const SketchSegment& seg : s->segments)
            for (const Eigen::Vector2d& q : {seg.from, seg.to}) {
                x0 = std::min(x0, q.x());
                x1 = std::max(x1, q.x());
                y0 = std::min(y0, q.y());
                y1 = std::max(y1, q.y());
            }
    const QRectF area(kMargin, kCaption + kMargin, width() - 2 * kMargin,
                      height() - kCaption - 2 * kMargin);
    const double span = std::max({x1 - x0, y1 - y0, 1e-9});
    const double k = std::min(area.width() / std::max(x1 - x0, span * 1e-3),
                              area.height() / std::max(y1 - y0, span * 1e-3));
    const double cx = area.center().x() - k * 0.5 * (x0 + x1);
    const double cy = area.center().y() + k * 0.5 * (y0 + y1);
    auto px = [&](const Eigen::Vector2d& q) { return QPointF(cx + k * q.x(), cy - k * q.y()); };

    QPen rest(QColor(0x99, 0x99, 0x99), 1.0, Qt::DashLine);
    p.setPen(rest);
    for (const SketchSegment& seg : m_rest.segments)
        p.drawLine(px(seg.from), px(seg.to));
    for (const SketchSegment& seg : m_deformed.segments) {
        const double w = seg.part == SketchPart::Element ? 3.0 : 2.0;
        p.setPen(QPen(colourOf(seg.part), w, Qt::SolidLine, Qt::RoundCap));
        p.drawLine(px(seg.from), px(seg.to));
        if (seg.part == SketchPart::Actuator && seg.actuator >= 0 &&
            seg.actuator < m_actuatorNames.size()) {
            // the name at the actuator's middle: above a horizontal one, beside a vertical one
            // on the side away from node j (two close vertical actuators' names never cross)
            p.setPen(colourOf(seg.part).darker(130));
            const QString name = m_actuatorNames[seg.actuator];
            const QPointF mid = 0.5 * (px(seg.from) + px(seg.to));
            const Eigen::Vector2d along = seg.to - seg.from;
            const double w = fontMetrics().horizontalAdvance(name);
            double x = mid.x() - 0.5 * w, y = mid.y() - 4.0;
            if (std::abs(along.y()) > std::abs(along.x())) {
                const bool left = seg.from.x() < m_deformed.nodeJ.x() - 1e-9;
                x = left ? mid.x() - w - 4.0 : mid.x() + 4.0;
                y = mid.y() + 0.5 * fontMetrics().ascent();
            }
            p.drawText(QPointF(std::clamp(x, 2.0, std::max(2.0, width() - w - 2.0)), y), name);
        }
    }
    // node i: a fixed support; node j: the control point
    const QPointF i = px(m_deformed.nodeI);
    QPainterPath support;
    support.moveTo(i);
    support.lineTo(i + QPointF(-7.0, 10.0));
    support.lineTo(i + QPointF(7.0, 10.0));
    support.closeSubpath();
    p.setPen(QPen(Qt::black, 1.0));
    p.setBrush(QColor(0xdd, 0xdd, 0xdd));
    p.drawPath(support);
    p.setBrush(colourOf(SketchPart::Element));
    p.drawEllipse(px(m_deformed.nodeJ), 3.5, 3.5);
}

} // namespace hsmu::gui
