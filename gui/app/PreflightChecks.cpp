#include "gui/app/PreflightChecks.h"

#include "core/config/TestConfig.h"

namespace hsmu::gui {

namespace {
QString label(const QString& key) {
    if (key == QLatin1String("dt"))
        return PreflightChecks::tr("time step dt [s]");
    if (key == QLatin1String("duration"))
        return PreflightChecks::tr("duration [s]");
    if (key == QLatin1String("groundMotion"))
        return PreflightChecks::tr("ground motion");
    if (key == QLatin1String("scale"))
        return PreflightChecks::tr("ground motion scale [-]");
    if (key == QLatin1String("integrator"))
        return PreflightChecks::tr("integrator");
    if (key == QLatin1String("controller"))
        return PreflightChecks::tr("controller");
    if (key == QLatin1String("steps"))
        return PreflightChecks::tr("steps");
    if (key == QLatin1String("pga"))
        return PreflightChecks::tr("PGA [m/s²]");
    return key;
}
} // namespace

QVariantMap PreflightChecks::runSettingsOf(const TestConfig& cfg, const QString& controller,
                                           const PreflightReport& report) {
    const GroundMotionSpec& gm = cfg.groundMotion;
    return {
        {QStringLiteral("dt"), QString::number(cfg.analysis.dt, 'g', 6)},
        {QStringLiteral("duration"), QString::number(cfg.analysis.duration, 'g', 6)},
        {QStringLiteral("groundMotion"),
         QString::fromStdString(gm.file.empty() ? gm.builtin : gm.file)},
        {QStringLiteral("scale"), QString::number(gm.scale, 'g', 6)},
        {QStringLiteral("integrator"), QString::fromStdString(cfg.analysis.integrator)},
        {QStringLiteral("controller"), controller},
        {QStringLiteral("steps"), QString::number(report.totalSteps)},
        {QStringLiteral("pga"), QString::number(report.pga, 'g', 4)},
    };
}

QStringList PreflightChecks::warnings(const PreflightReport& report, const QVariantMap& current,
                                      const QVariantMap& lastRun) {
    QStringList out;
    if (report.totalSteps > kUnusualSteps)
        out << tr("Unusual step count: %L1 steps (more than %L2); check dt and the duration.")
                   .arg(report.totalSteps)
                   .arg(kUnusualSteps);
    if (report.pga > kUnusualPga)
        out << tr("Unusual PGA: %1 m/s² (above %2 m/s²); check the ground motion scale.")
                   .arg(QString::number(report.pga, 'f', 2))
                   .arg(kUnusualPga);
    if (!(report.pga > 0.0))
        out << tr("The ground motion is zero (PGA 0 m/s²).");
    if (report.dt > 0.0 && report.dt < kSmallDt)
        out << tr("Very small time step: dt = %1 s.").arg(report.dt);
    if (!lastRun.isEmpty())
        for (auto it = current.begin(); it != current.end(); ++it) {
            const QString before = lastRun.value(it.key()).toString();
            if (lastRun.contains(it.key()) && before != it.value().toString())
                out << tr("Changed since the last run: %1 %2 -> %3")
                           .arg(label(it.key()), before, it.value().toString());
        }
    return out;
}

} // namespace hsmu::gui
