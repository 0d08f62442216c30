#include "gui/app/AlarmText.h"

#include "core/integration/StabilityCheck.h"
#include "core/util/ReasonText.h"

namespace hsmu::gui {

namespace {
QStringList qt(const std::vector<std::string>& args) {
    QStringList out;
    for (const std::string& a : args)
        out << QString::fromStdString(a);
    return out;
}
} // namespace

QString AlarmText::reason(const QString& english) {
    if (const auto coded = parseReason(english.toStdString())) {
        const QString text = translate(coded->code, qt(coded->args));
        if (!text.isNull())
            return text;
    }
    // "<element>: <reason>": core's prefix of an element's reason (the name stays).
    const qsizetype colon = english.indexOf(QLatin1String(": "));
    if (colon > 0) {
        const QString rest = english.mid(colon + 2);
        const QString translated = reason(rest);
        if (translated != rest)
            return tr("%1: %2").arg(english.left(colon), translated);
    }
    return english;
}

QString AlarmText::describe(const std::string& code, const QStringList& a,
                            const QString& english) {
    const QString text = translate(code, a);
    return text.isNull() ? reason(english) : text;
}

QString AlarmText::translate(const std::string& code, const QStringList& a) {
    const auto n = a.size();
    const auto is = [&](const char* c, qsizetype count) { return code == c && n == count; };
    // Hold reasons.
    if (is("operator-hold", 0))
        return tr("operator hold");
    if (is("operator", 0))
        return tr("operator");
    if (is("operator-console", 0))
        return tr("operator at the console");
    if (is("emergency-hold-by-operator", 0))
        return tr("emergency hold by the operator");
    if (is("stopped-by-operator", 0))
        return tr("stopped by the operator");
    if (is("emergency-hold-fault", 2))
        return tr("emergency hold: %1 (%2)").arg(reason(a[0]), reason(a[1]));
    if (is("emergency-hold", 1))
        return tr("emergency hold: %1").arg(reason(a[0]));
    if (is("prediction-not-finite", 0))
        return tr("predicted displacement is not finite");
    if (is("response-not-finite", 0))
        return tr("restoring force or response is not finite");
    // Safety limits.
    if (is("limit-target-not-finite", 0))
        return tr("target deformation is not a finite number");
    if (is("limit-target", 2))
        return tr("target deformation |d| = %1 exceeds the limit %2").arg(a[0], a[1]);
    if (is("limit-increment", 2))
        return tr("target increment |d - d_last| = %1 exceeds the limit %2").arg(a[0], a[1]);
    if (is("limit-force-not-finite", 0))
        return tr("measured force is not a finite number");
    if (is("limit-force", 2))
        return tr("measured force |F| = %1 exceeds the limit %2").arg(a[0], a[1]);
    if (is("limit-measured-not-finite", 0))
        return tr("measured deformation is not a finite number");
    if (is("limit-measured", 3))
        return tr("measured deformation |d| = %1 exceeds the limit %2 (+%3 % tolerance)")
            .arg(a[0], a[1], a[2]);
    // Stability.
    if (is("stability-forced", 1))
        return tr("%1 (forced by the operator)").arg(reason(a[0]));
    if (is("stability-ok", 5))
        return tr("%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5")
            .arg(a[0], a[1], a[2], a[3], a[4]);
    if (is("stability-unstable", 6))
        return tr("%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 "
                  "rad/s, dt = %5 s); use dt <= %6 s or the alphaOS integrator")
            .arg(a[0], a[1], a[2], a[3], a[4], a[5]);
    if (is("updated-model-may-diverge", 4))
        return tr("updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), "
                  "limit %4; K0 and damping kept from the start: the explicit integration of "
                  "the updated model may diverge")
            .arg(a[0], a[1], a[2], a[3]);
    if (is("updated-model", 4))
        return tr("updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), "
                  "limit %4; K0 and damping kept from the start")
            .arg(a[0], a[1], a[2], a[3]);
    // Names of built-in records.
    if (is("synthetic-motion", 1))
        return tr("synthetic Kanai-Tajimi (seed %1)").arg(a[0]);
    // Alarms of the test and its inspector.
    if (is("test-held", 1))
        return tr("test held: %1").arg(reason(a[0]));
    if (is("test-resumed", 0))
        return tr("test resumed");
    if (is("fit-error", 2))
        return tr("model error %1 % above the threshold %2 %").arg(a[0], a[1]);
    if (is("fracture", 2))
        return tr("sudden strength loss: measured force %1 short of the model's by %2")
            .arg(a[0], a[1]);
    if (is("estimator-rejected", 1))
        return tr("identification step rejected: %1").arg(reason(a[0]));
    if (is("tracking", 2))
        return tr("actuator tracking error J2 = %1 % (delay J1 = %2 s)").arg(a[0], a[1]);
    if (is("parameter-pinned", 3))
        return tr("%1 has been at its bound %2 for %3 s").arg(a[0], a[1], a[2]);
    if (is("auxiliary-not-converged", 1))
        return tr("auxiliary model did not converge at deformation %1").arg(a[0]);
    if (is("approval-queue-full", 1))
        return tr("update not applied: the approval queue is full (%1 proposals pending); "
                  "this and later offers are in the record until the operator decides")
            .arg(a[0]);
    return {};
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
