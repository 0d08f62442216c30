#include "gui/app/AlarmText.h"

#include "core/integration/StabilityCheck.h"
#include "core/util/ReasonText.h"

namespace hsmu::gui {

namespace {
// core's templates translated by the table (codes added after the hand-written ones of
// translate()): the source text is core's English template, every argument is itself
// translated when it is one of core's texts (nested reasons).
struct Entry {
    const char* code;
    const char* source;
};
constexpr Entry kEntries[] = {
    {"link-down", QT_TRANSLATE_NOOP("AlarmText", "link to %1 is down (%2); resume to reconnect")},
    {"link-fault", QT_TRANSLATE_NOOP("AlarmText", "link to %1: %2")},
    {"controller-refused", QT_TRANSLATE_NOOP("AlarmText", "controller at %1: %2")},
    {"link-holding", QT_TRANSLATE_NOOP("AlarmText", "TCP link is holding: %1")},
    {"no-connection-within", QT_TRANSLATE_NOOP("AlarmText", "no connection to %1 within %2 s")},
    {"cannot-connect", QT_TRANSLATE_NOOP("AlarmText", "cannot connect to %1: %2")},
    {"cannot-resolve", QT_TRANSLATE_NOOP("AlarmText", "cannot resolve %1: %2")},
    {"controller-closed", QT_TRANSLATE_NOOP("AlarmText", "the controller closed the connection")},
    {"peer-closed", QT_TRANSLATE_NOOP("AlarmText", "the peer closed the connection")},
    {"connection-lost-sending", QT_TRANSLATE_NOOP("AlarmText", "connection lost while sending: %1")},
    {"connection-lost", QT_TRANSLATE_NOOP("AlarmText", "connection lost: %1")},
    {"malformed-frame", QT_TRANSLATE_NOOP("AlarmText", "malformed frame from the controller: %1")},
    {"controller-silent", QT_TRANSLATE_NOOP("AlarmText", "the controller was silent for %1 s")},
    {"not-connected-because", QT_TRANSLATE_NOOP("AlarmText", "not connected: %1")},
    {"not-connected", QT_TRANSLATE_NOOP("AlarmText", "not connected")},
    {"no-reply-within", QT_TRANSLATE_NOOP("AlarmText", "no reply within %1 s")},
    {"closed-by-console", QT_TRANSLATE_NOOP("AlarmText", "closed by the console")},
    {"closed-by-emergency-hold", QT_TRANSLATE_NOOP("AlarmText", "closed by an emergency hold")},
    {"no-hello-answer", QT_TRANSLATE_NOOP("AlarmText", "no answer to the hello")},
    {"no-measurement-for-step", QT_TRANSLATE_NOOP("AlarmText", "no measurement for step %1")},
    {"controller-step-mismatch",
     QT_TRANSLATE_NOOP("AlarmText",
                       "the controller's specimen is at step %1 but the test committed %2 (was it "
                       "restarted without its --state file?); cannot resume without a jump")},
    {"specimen-holds", QT_TRANSLATE_NOOP("AlarmText", "specimen '%1' holds: %2")},
    {"interlock", QT_TRANSLATE_NOOP("AlarmText", "interlock: %1")},
    {"specimen-fault", QT_TRANSLATE_NOOP("AlarmText", "specimen fault: %1")},
    {"controller-fault", QT_TRANSLATE_NOOP("AlarmText", "controller fault: %1")},
    {"actuator-limit",
     QT_TRANSLATE_NOOP("AlarmText", "actuator position |d| = %1 exceeds the limit %2")},
    {"console-hold", QT_TRANSLATE_NOOP("AlarmText", "console hold")},
    {"wrong-token", QT_TRANSLATE_NOOP("AlarmText", "wrong token")},
    {"controller-busy",
     QT_TRANSLATE_NOOP("AlarmText", "another console session is running a test on this "
                                    "controller (one session at a time)")},
    {"no-specimen-named",
     QT_TRANSLATE_NOOP("AlarmText", "this controller has no specimen named '%1'")},
    {"held-from-previous-session",
     QT_TRANSLATE_NOOP("AlarmText", "held from the previous console session: %1")},
    {"virtual-specimen-fracture",
     QT_TRANSLATE_NOOP("AlarmText", "virtual specimen (%1 law, force noise std %2, %3 actuator, "
                                    "fracture event)")},
    {"virtual-specimen",
     QT_TRANSLATE_NOOP("AlarmText", "virtual specimen (%1 law, force noise std %2, %3 actuator)")},
    {"controller-specimen-fracture",
     QT_TRANSLATE_NOOP("AlarmText",
                       "specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 "
                       "actuator, %5 pace, %6 Hz predictor-corrector, fracture event), %7 "
                       "committed steps")},
    {"controller-specimen",
     QT_TRANSLATE_NOOP("AlarmText",
                       "specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 "
                       "actuator, %5 pace, %6 Hz predictor-corrector), %7 committed steps")},
    {"tcp-link-to", QT_TRANSLATE_NOOP("AlarmText", "TCP link %1 to %2")},
    {"specimen-named", QT_TRANSLATE_NOOP("AlarmText", "specimen '%1'")},
    {"openfresco-link", QT_TRANSLATE_NOOP("AlarmText", "%1 link %2 for specimen '%3' (%4)")},
    {"prediction-rejected", QT_TRANSLATE_NOOP("AlarmText", "prediction rejected: %1")},
    {"update-rejected", QT_TRANSLATE_NOOP("AlarmText", "update rejected: %1")},
    {"bouc-wen-integration-failed",
     QT_TRANSLATE_NOOP("AlarmText", "Bouc-Wen integration failed (%1): %2")},
    {"state-not-advanced",
     QT_TRANSLATE_NOOP("AlarmText", "%1; z and e could not be advanced either: step skipped")},
    {"ukf-state-not-finite", QT_TRANSLATE_NOOP("AlarmText", "the state is not finite")},
    {"ukf-measurement-not-finite", QT_TRANSLATE_NOOP("AlarmText", "the measurement is not finite")},
    {"ukf-prediction-not-finite",
     QT_TRANSLATE_NOOP("AlarmText", "the predicted measurement is not finite")},
    {"ukf-innovation-not-pd",
     QT_TRANSLATE_NOOP("AlarmText",
                       "the innovation covariance is not positive definite (check R)")},
    {"ukf-not-initialized", QT_TRANSLATE_NOOP("AlarmText", "the filter has not been initialized")},
    {"nelder-mead-failed", QT_TRANSLATE_NOOP("AlarmText", "Nelder-Mead fit failed: %1")},
    {"nelder-mead-kept",
     QT_TRANSLATE_NOOP("AlarmText", "Nelder-Mead trigger %1 kept the parameters (RMS %2 not "
                                    "improved, %3 evaluations, %4 ms)")},
    {"nelder-mead-refit",
     QT_TRANSLATE_NOOP("AlarmText",
                       "Nelder-Mead trigger %1: RMS force error %2 -> %3 (%4 evaluations, %5 ms)")},
    {"measured-not-finite-skipped",
     QT_TRANSLATE_NOOP("AlarmText",
                       "the measured deformation or force is not finite: step skipped")},
    {"file-line", QT_TRANSLATE_NOOP("AlarmText", "%1 line %2: %3")},
    {"file-missing", QT_TRANSLATE_NOOP("AlarmText", "cannot open '%1': the file does not exist")},
    {"file-is-folder",
     QT_TRANSLATE_NOOP("AlarmText", "cannot open '%1': it is a folder, not a file")},
    {"file-not-regular",
     QT_TRANSLATE_NOOP("AlarmText",
                       "cannot read '%1': not a regular file (a device, pipe or socket)")},
    {"file-unreadable",
     QT_TRANSLATE_NOOP("AlarmText", "cannot open '%1' for reading (permissions?)")},
    {"file-not-text",
     QT_TRANSLATE_NOOP("AlarmText", "'%1' is not a text file (binary data at byte %2)")},
    {"motion-empty-at2",
     QT_TRANSLATE_NOOP("AlarmText", "the file is empty (expected a PEER AT2 record)")},
    {"motion-empty", QT_TRANSLATE_NOOP("AlarmText", "the file is empty (no acceleration values)")},
    {"motion-no-data",
     QT_TRANSLATE_NOOP("AlarmText", "no data lines (only comments or blank lines)")},
    {"motion-unknown-empty",
     QT_TRANSLATE_NOOP("AlarmText",
                       "the file is empty: expected an AT2 header ('NPTS=..., DT=...' on line 4), "
                       "two columns (time, acceleration) or one column of values")},
    {"motion-unknown-no-data",
     QT_TRANSLATE_NOOP("AlarmText",
                       "no data lines: expected an AT2 header ('NPTS=..., DT=...' on line 4), two "
                       "columns (time, acceleration) or one column of values")},
    {"expected-number", QT_TRANSLATE_NOOP("AlarmText", "expected a number, found %1")},
    {"non-finite-value", QT_TRANSLATE_NOOP("AlarmText", "non-finite value %1")},
    {"dt-not-positive", QT_TRANSLATE_NOOP("AlarmText", "the time step dt must be > 0 s, got %1")},
    {"two-columns",
     QT_TRANSLATE_NOOP("AlarmText", "expected two columns (time, acceleration), found %1 value(s)")},
    {"one-sample",
     QT_TRANSLATE_NOOP("AlarmText", "only one sample: the time step cannot be determined")},
    {"time-not-increasing", QT_TRANSLATE_NOOP("AlarmText", "time must increase: %1 s follows %2 s")},
    {"non-uniform-step",
     QT_TRANSLATE_NOOP("AlarmText",
                       "non-uniform time step: %1 s follows %2 s (step %3 s, mean step %4 s); a "
                       "uniform step is required (tolerance 1e-6 relative)")},
    {"single-column-needs-dt",
     QT_TRANSLATE_NOOP("AlarmText", "a single column of acceleration values needs the time step "
                                    "dt, and none was given")},
    {"config-cannot-open", QT_TRANSLATE_NOOP("AlarmText", "cannot open the configuration file")},
    {"config-not-regular",
     QT_TRANSLATE_NOOP("AlarmText", "not a regular file (a folder, device, pipe or socket)")},
    {"config-not-json", QT_TRANSLATE_NOOP("AlarmText", "not valid JSON (%1)")},
    {"record-missing", QT_TRANSLATE_NOOP("AlarmText", "cannot be opened (no such file)")},
    {"record-not-hdf5", QT_TRANSLATE_NOOP("AlarmText", "not an HSMU record (not an HDF5 file)")},
    {"record-no-schema",
     QT_TRANSLATE_NOOP("AlarmText", "not an HSMU record (no schema_version attribute)")},
    {"record-damaged", QT_TRANSLATE_NOOP("AlarmText", "damaged record (%1)")},
    {"record-no-step", QT_TRANSLATE_NOOP("AlarmText", "the record holds no step")},
};

// %1..%9 of `text` replaced by args in one pass (an argument's own "%1" stays as it is).
QString substitute(const QString& text, const QStringList& args) {
    QString out;
    out.reserve(text.size() + 32);
    for (qsizetype i = 0; i < text.size(); ++i) {
        const QChar c = text[i];
        if (c == QLatin1Char('%') && i + 1 < text.size() && text[i + 1] >= QLatin1Char('1') &&
            text[i + 1] <= QLatin1Char('9')) {
            const qsizetype index = text[i + 1].unicode() - '1';
            if (index < args.size())
                out += args[index];
            ++i;
        } else {
            out += c;
        }
    }
    return out;
}

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
        const QString head = english.left(colon), rest = english.mid(colon + 2);
        const QString translated = reason(rest), shownHead = reason(head);
        if (translated != rest || shownHead != head)
            return tr("%1: %2").arg(shownHead, translated);
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
    if (is("test-resumed-reconnect", 0))
        return tr("test resumed after an automatic reconnect");
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
    if (is("rths-not-followed", 1))
        return tr("RTHS run not followed: %1").arg(reason(a[0]));
    if (is("rths-held", 1))
        return tr("RTHS run held: %1").arg(reason(a[0]));
    if (is("rths-j1-warning", 2))
        return tr("live delay J1 = %1 ms over the warning threshold %2 ms").arg(a[0], a[1]);
    if (is("rths-j1-critical", 2))
        return tr("live delay J1 = %1 ms over the critical threshold %2 ms").arg(a[0], a[1]);
    if (is("rths-j2-warning", 2))
        return tr("live tracking error J2 = %1 % over the warning threshold %2 %").arg(a[0], a[1]);
    if (is("rths-j2-critical", 2))
        return tr("live tracking error J2 = %1 % over the critical threshold %2 %").arg(a[0], a[1]);
    if (is("parameter-pinned", 3))
        return tr("%1 has been at its bound %2 for %3 s").arg(a[0], a[1], a[2]);
    if (is("auxiliary-not-converged", 1))
        return tr("auxiliary model did not converge at deformation %1").arg(a[0]);
    if (is("offsets-proposed", 2))
        return tr("offsets proposed for the twins: u0 = %1, F0 = %2 (they apply only when the "
                  "operator approves them)")
            .arg(a[0], a[1]);
    if (is("approval-queue-full", 1))
        return tr("update not applied: the approval queue is full (%1 proposals pending); "
                  "this and later offers are in the record until the operator decides")
            .arg(a[0]);
    for (const Entry& e : kEntries) {
        if (code != e.code || n != reasonArgumentCount(e.code))
            continue;
        QStringList shown;
        for (const QString& arg : a)
            shown << word(reason(arg));
        return substitute(QCoreApplication::translate("AlarmText", e.source), shown);
    }
    return {};
}

QString AlarmText::word(const QString& english) {
    // The fixed words core puts into its descriptions (actuator models, paces).
    if (english == QLatin1String("ideal"))
        return tr("ideal");
    if (english == QLatin1String("lag"))
        return tr("lag");
    if (english == QLatin1String("delay"))
        return tr("delay");
    if (english == QLatin1String("fast"))
        return tr("fast");
    if (english == QLatin1String("real-time"))
        return tr("real-time");
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
