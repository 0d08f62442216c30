#include "gui/app/OperatorEvent.h"

#include "core/updating/Reporter.h"
#include "gui/app/PendingUpdatesPanel.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QRegularExpression>

#include <cstring>

namespace hsmu::gui {

namespace {
bool is(const std::string& action, const char* key) {
    return action == key;
}

// A policy as the record names it ("onApproval", "everyNSteps N=10"), in the operator's words.
QString policyText(const QString& value) {
    const QString name = value.section(QLatin1Char(' '), 0, 0);
    const auto policy = parseReporterPolicy(name.toStdString());
    if (!policy)
        return value;
    const QString rest = value.section(QLatin1Char(' '), 1);
    const QString text = PendingUpdatesPanel::describe(*policy);
    return rest.isEmpty() ? text : text + QLatin1Char(' ') + rest;
}
// kLoadedSpecimen: "<element>: <N> committed steps, last deformation <d> <unit>" in words.
QString loadedSpecimenText(const QString& old, const QString& choice) {
    static const QRegularExpression form(
        QStringLiteral("^(.*): (\\d+) committed steps, last deformation (\\S+) ?(.*)$"));
    const QRegularExpressionMatch m = form.match(old);
    const QString specimen =
        m.hasMatch() ? OperatorEvent::tr("%1 (%L2 committed steps, last deformation %3 %4)")
                           .arg(m.captured(1))
                           .arg(m.captured(2).toULongLong())
                           .arg(m.captured(3), m.captured(4))
                           .trimmed()
                     : old;
    if (choice == QLatin1String("continue"))
        return OperatorEvent::tr("specimen loaded by an earlier test: %1; the operator continues "
                                 "on it")
            .arg(specimen);
    if (choice == QLatin1String("fresh"))
        return OperatorEvent::tr("specimen loaded by an earlier test: %1; the operator chose a "
                                 "fresh specimen, its controller reset it to step 0")
            .arg(specimen);
    return OperatorEvent::tr("specimen loaded by an earlier test: %1; the operator chose a fresh "
                             "specimen, its controller refused (nothing changed)")
        .arg(specimen);
}
} // namespace

OperatorEvent OperatorEvent::now(int step, double time, std::string action, std::string oldValue,
                                 std::string newValue) {
    OperatorEvent e;
    e.step = step;
    e.time = time;
    e.wallTime = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
    e.action = std::move(action);
    e.oldValue = std::move(oldValue);
    e.newValue = std::move(newValue);
    return e;
}

std::string OperatorEvent::recordText() const {
    return "operator-event action=" + action + "; old=" + oldValue + "; new=" + newValue +
           "; wall=" + wallTime.toStdString();
}

std::optional<OperatorEvent> OperatorEvent::fromRecordText(const std::string& text) {
    // "operator-event action=<key>; old=<value>; new=<value>; wall=<time>": the values may
    // hold "; " themselves, so each field ends where the next field's key begins.
    static const char* const kKeys[] = {"operator-event action=", "; old=", "; new=", "; wall="};
    std::size_t at[4];
    std::size_t from = 0;
    for (int k = 0; k < 4; ++k) {
        at[k] = text.find(kKeys[k], from);
        if (at[k] == std::string::npos || (k == 0 && at[k] != 0))
            return std::nullopt;
        from = at[k] + std::strlen(kKeys[k]);
    }
    const auto field = [&](int k) {
        const std::size_t begin = at[k] + std::strlen(kKeys[k]);
        return text.substr(begin, (k < 3 ? at[k + 1] : text.size()) - begin);
    };
    OperatorEvent e;
    e.action = field(0);
    e.oldValue = field(1);
    e.newValue = field(2);
    e.wallTime = QString::fromStdString(field(3));
    return e;
}

QString OperatorEvent::describe() const {
    const QString o = QString::fromStdString(oldValue);
    const QString n = QString::fromStdString(newValue);
    QString what;
    if (is(action, kPreflightConfirmed))
        what = tr("pre-flight confirmed by the operator (zero offsets)");
    else if (is(action, kPreflightSkipped))
        what = tr("pre-flight check skipped: the test was started from the command line "
                  "(--start)");
    else if (is(action, kStart))
        what = tr("test started by the operator");
    else if (is(action, kPause))
        what = tr("paused by the operator");
    else if (is(action, kSingleStep))
        what = tr("single step by the operator");
    else if (is(action, kResume))
        what = tr("resumed by the operator");
    else if (is(action, kHold))
        what = n == QStringLiteral("not-armed")
                   ? tr("emergency hold before the test was armed: nothing is armed, the "
                        "pre-flight check must be confirmed again")
                   : tr("emergency hold by the operator");
    else if (is(action, kStop))
        what = tr("test ended by the operator, data kept");
    else if (is(action, kApprove)) // old: "#id element values", new: the values applied
        what = tr("update %1 approved by the operator: %2 -> %3")
                   .arg(o.section(QLatin1Char(' '), 0, 0), o.section(QLatin1Char(' '), 1), n);
    else if (is(action, kReject))
        what = tr("update %1 rejected by the operator (%2)").arg(o, n);
    else if (is(action, kApproveOffsets)) // old: "#id targets", new: the offsets applied
        what = tr("offsets %1 approved by the operator for %2: %3")
                   .arg(o.section(QLatin1Char(' '), 0, 0), o.section(QLatin1Char(' '), 1), n);
    else if (is(action, kRejectOffsets))
        what = tr("offsets %1 rejected by the operator (%2)").arg(o, n);
    else if (is(action, kBounds))
        what = tr("bounds changed: %1 -> %2").arg(o, n);
    else if (is(action, kLock))
        what = tr("lock changed: %1 -> %2").arg(o, n);
    else if (is(action, kThreshold))
        what = tr("fit-error threshold changed: %1 -> %2").arg(o, n);
    else if (is(action, kPolicy))
        what = tr("updating policy changed: %1 -> %2").arg(policyText(o), policyText(n));
    else if (is(action, kLoadedSpecimen))
        what = loadedSpecimenText(o, n);
    else if (is(action, kNote))
        what = tr("note recorded: %1").arg(n);
    else
        what = QString::fromStdString(action);
    return tr("%1 (wall time %2)").arg(what, wallTime);
}

} // namespace hsmu::gui
