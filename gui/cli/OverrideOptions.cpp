#include "gui/cli/OverrideOptions.h"

#include <QCommandLineParser>

#include <cmath>

namespace hsmu::gui {

OverrideOptions::OverrideOptions()
    : m_groundMotion(QStringLiteral("ground-motion"), tr("Ground-motion record file."),
                     QStringLiteral("file")),
      m_recordDt(QStringLiteral("record-dt"),
                 tr("The record's own sample step [s] (a one-column file of values needs it)."),
                 QStringLiteral("dt")),
      m_scale(QStringLiteral("scale"), tr("Ground-motion scale factor."), QStringLiteral("s")),
      m_dt(QStringLiteral("dt"), tr("Integration step [s]."), QStringLiteral("dt")),
      m_duration(QStringLiteral("duration"), tr("Test duration [s]."), QStringLiteral("t")) {}

void OverrideOptions::addTo(QCommandLineParser& p) const {
    p.addOptions({m_groundMotion, m_recordDt, m_scale, m_dt, m_duration});
}

std::optional<QString> OverrideOptions::number(const QCommandLineParser& p,
                                               const QCommandLineOption& o,
                                               std::optional<double>& target, bool positive) {
    if (!p.isSet(o))
        return std::nullopt;
    bool ok = false;
    const double v = p.value(o).toDouble(&ok);
    if (!ok || !std::isfinite(v) || (positive && v <= 0.0))
        return tr("--%1: expected a %2 number, found '%3'")
            .arg(o.names().front(), positive ? tr("positive") : QString(), p.value(o))
            .simplified();
    target = v;
    return std::nullopt;
}

std::optional<QString> OverrideOptions::read(const QCommandLineParser& p,
                                             ConfigOverrides& overrides) const {
    overrides.groundMotionFile = p.value(m_groundMotion);
    if (auto e = number(p, m_recordDt, overrides.recordDt, true))
        return e;
    if (auto e = number(p, m_scale, overrides.scale, false))
        return e;
    if (auto e = number(p, m_dt, overrides.dt, true))
        return e;
    if (auto e = number(p, m_duration, overrides.duration, true))
        return e;
    return std::nullopt;
}

} // namespace hsmu::gui
