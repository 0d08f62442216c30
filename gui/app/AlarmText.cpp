#include "gui/app/AlarmText.h"

#include "core/integration/StabilityCheck.h"

namespace hsmu::gui {

QString AlarmText::reason(const QString& english) {
    if (english == QLatin1String("operator hold"))
        return tr("operator hold");
    if (english == QLatin1String("predicted displacement is not finite"))
        return tr("predicted displacement is not finite");
    if (english == QLatin1String("restoring force or response is not finite"))
        return tr("restoring force or response is not finite");
    return english;
}

QString AlarmText::describe(const std::string& code, const QStringList& a,
                            const QString& english) {
    const auto n = a.size();
    if (code == "test-held" && n == 1)
        return tr("test held: %1").arg(reason(a[0]));
    if (code == "test-resumed" && n == 0)
        return tr("test resumed");
    if (code == "fit-error" && n == 2)
        return tr("model error %1 % above the threshold %2 %").arg(a[0], a[1]);
    if (code == "fracture" && n == 2)
        return tr("sudden strength loss: measured force %1 short of the model's by %2")
            .arg(a[0], a[1]);
    if (code == "estimator-rejected" && n == 1)
        return tr("identification step rejected: %1").arg(a[0]);
    if (code == "tracking" && n == 2)
        return tr("actuator tracking error J2 = %1 % (delay J1 = %2 s)").arg(a[0], a[1]);
    if (code == "parameter-pinned" && n == 3)
        return tr("%1 has been at its bound %2 for %3 s").arg(a[0], a[1], a[2]);
    if (code == "approval-queue-full" && n == 1)
        return tr("update not applied: the approval queue is full (%1 proposals pending); "
                  "this and later offers are in the record until the operator decides")
            .arg(a[0]);
    return english;
}

QString AlarmText::stability(const StabilityReport& r, const QString& integrator, double dt) {
    const auto g = [](double v) { return QString::number(v, 'g', 4); };
    if (r.stable)
        return tr("%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5")
            .arg(integrator, g(r.omegaDt), g(r.omegaMax), g(dt), g(r.limit));
    return tr("%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 "
              "rad/s, dt = %5 s); use dt <= %6 s or the alphaOS integrator")
        .arg(integrator, g(r.omegaDt), g(r.limit), g(r.omegaMax), g(dt), g(r.maxStableDt));
}

} // namespace hsmu::gui
