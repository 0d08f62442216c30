#include "gui/app/ActuatorLimitText.h"

namespace hsmu::gui {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 6);
}

} // namespace

QString ActuatorLimitText::line(const std::string& element, const ActuatorLimitLine& l) {
    const QString who =
        tr("%1, actuator '%2' (%3)")
            .arg(QString::fromStdString(element), QString::fromStdString(l.actuator),
                 l.mode == ActuatorMode::Force ? tr("force control") : tr("displacement control"));
    QString what;
    switch (l.quantity) {
    case LimitQuantity::Stroke:
        what = tr("stroke |s|");
        break;
    case LimitQuantity::Force:
        what = tr("force |F|");
        break;
    case LimitQuantity::Increment:
        what = tr("stroke increment |Δs| per step");
        break;
    }
    const QString unit =
        l.quantity == LimitQuantity::Force ? QStringLiteral("kN") : QStringLiteral("m");
    switch (l.verdict) {
    case LimitVerdict::Pass:
        return tr("PASS  %1: %2 up to %3 %4 (t = %5 s), within the limit %6 %4")
            .arg(who, what, number(l.reach), unit, number(l.reachTime), number(l.limit));
    case LimitVerdict::Exceeded:
        return tr("FAIL  %1: %2 reaches %3 %4 (t = %5 s), past the limit %6 %4: the test will "
                  "hold at that step")
            .arg(who, what, number(l.reach), unit, number(l.reachTime), number(l.limit));
    case LimitVerdict::DuringRun:
        return tr("%1: %2 limit %3 %4, checked at every step (it depends on the specimen's "
                  "response)")
            .arg(who, what, number(l.limit), unit);
    case LimitVerdict::NoLimit:
        return tr("%1: no %2 limit").arg(who, what);
    }
    return who;
}

} // namespace hsmu::gui
