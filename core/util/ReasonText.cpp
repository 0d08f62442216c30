#include "core/util/ReasonText.h"

#include <algorithm>
#include <cstring>

namespace hsmu {

namespace {
struct Template {
    const char* code;
    const char* english; ///< %1..%9 stand for the arguments
};

// Longer, more specific templates first: parseReason takes the first that matches.
constexpr Template kTemplates[] = {
    // A hold's reason (HybridTest, TestSession, the console).
    {"operator-hold", "operator hold"},
    {"operator", "operator"},
    {"operator-console", "operator at the console"},
    {"emergency-hold-by-operator", "emergency hold by the operator"},
    {"stopped-by-operator", "stopped by the operator"},
    {"emergency-hold-fault", "emergency hold: %1 (%2)"},
    {"emergency-hold", "emergency hold: %1"},
    {"prediction-not-finite", "predicted displacement is not finite"},
    {"response-not-finite", "restoring force or response is not finite"},
    // Safety limits (SafetyLimits; an element's prefixes its name: "<element>: <reason>").
    {"limit-target-not-finite", "target deformation is not a finite number"},
    {"limit-target", "target deformation |d| = %1 exceeds the limit %2"},
    {"limit-increment", "target increment |d - d_last| = %1 exceeds the limit %2"},
    {"limit-force-not-finite", "measured force is not a finite number"},
    {"limit-force", "measured force |F| = %1 exceeds the limit %2"},
    {"limit-measured-not-finite", "measured deformation is not a finite number"},
    {"limit-measured", "measured deformation |d| = %1 exceeds the limit %2 (+%3% tolerance)"},
    // Stability (StabilityCheck, HybridTest).
    {"stability-forced", "%1 (forced by the operator)"},
    {"stability-ok",
     "%1: omega_max dt = %2 (omega_max = %3 rad/s, dt = %4 s) within the limit %5"},
    {"stability-unstable",
     "%1 is unstable for this model: omega_max dt = %2 exceeds %3 (omega_max = %4 rad/s, "
     "dt = %5 s); use dt <= %6 s or the alphaOS integrator"},
    {"updated-model-may-diverge",
     "updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 "
     "and damping kept from the start: the explicit integration of the updated model may "
     "diverge"},
    {"updated-model",
     "updated model: omega_max dt = %1 (omega_max = %2 rad/s, %3 at the start), limit %4; K0 "
     "and damping kept from the start"},
    // Names of built-in records (core/groundmotion).
    {"synthetic-motion", "synthetic Kanai-Tajimi (seed %1)"},
    // Alarms of the test and its inspector (Alarm::code is the same code).
    {"test-held", "test held: %1"},
    {"test-resumed-reconnect", "test resumed after an automatic reconnect"},
    {"test-resumed", "test resumed"},
    {"fit-error", "model error %1 % above the threshold %2 %"},
    {"fracture", "sudden strength loss: measured force %1 short of the model's by %2"},
    {"estimator-rejected", "identification step rejected: %1"},
    {"tracking", "actuator tracking error J2 = %1 % (delay J1 = %2 s)"},
    {"parameter-pinned", "%1 has been at its bound %2 for %3 s"},
    {"approval-queue-full",
     "update not applied: approval queue full (%1 proposals pending): not queued (this and "
     "later offers are in the record until the operator decides)"},
    {"auxiliary-not-converged", "auxiliary model did not converge at deformation %1"},
    // The link to a controller and the controller's own faults (comms: TcpControl, LinkClient,
    // OpenFrescoControl, OfSocket; hsmu-controller's SpecimenStation and ControllerServer).
    {"link-down", "link to %1 is down (%2); resume to reconnect"},
    {"link-fault", "link to %1: %2"},
    {"controller-refused", "controller at %1: %2"},
    {"link-holding", "TCP link is holding: %1"},
    {"no-connection-within", "no connection to %1 within %2 s"},
    {"cannot-connect", "cannot connect to %1: %2"},
    {"cannot-resolve", "cannot resolve %1: %2"},
    {"controller-closed", "the controller closed the connection"},
    {"peer-closed", "the peer closed the connection"},
    {"connection-lost-sending", "connection lost while sending: %1"},
    {"connection-lost", "connection lost: %1"},
    {"malformed-frame", "malformed frame from the controller: %1"},
    {"controller-silent", "the controller was silent for %1 s"},
    {"not-connected-because", "not connected: %1"},
    {"not-connected", "not connected"},
    {"no-reply-within", "no reply within %1 s"},
    {"closed-by-console", "closed by the console"},
    {"closed-by-emergency-hold", "closed by an emergency hold"},
    {"no-hello-answer", "no answer to the hello"},
    {"no-measurement-for-step", "no measurement for step %1"},
    {"controller-step-mismatch",
     "the controller's specimen is at step %1 but the test committed %2 (was it restarted "
     "without its --state file?); cannot resume without a jump"},
    {"specimen-holds", "specimen '%1' holds: %2"},
    {"interlock", "interlock: %1"},
    {"specimen-fault", "specimen fault: %1"},
    {"controller-fault", "controller fault: %1"},
    {"actuator-limit", "actuator position |d| = %1 exceeds the limit %2"},
    {"console-hold", "console hold"},
    {"wrong-token", "wrong token"},
    {"controller-busy",
     "another console session is running a test on this controller (one session at a time)"},
    {"no-specimen-named", "this controller has no specimen named '%1'"},
    {"held-from-previous-session", "held from the previous console session: %1"},
    // What drives a specimen (a control's description, shown in pre-flight).
    {"virtual-specimen-fracture",
     "virtual specimen (%1 law, force noise std %2, %3 actuator, fracture event)"},
    {"virtual-specimen", "virtual specimen (%1 law, force noise std %2, %3 actuator)"},
    {"controller-specimen-fracture",
     "specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz "
     "predictor-corrector, fracture event), %7 committed steps"},
    {"controller-specimen",
     "specimen '%1' on hsmu-controller (%2 law, force noise std %3, %4 actuator, %5 pace, %6 Hz "
     "predictor-corrector), %7 committed steps"},
    {"tcp-link-to", "TCP link %1 to %2"},
    {"specimen-named", "specimen '%1'"},
    {"openfresco-link", "%1 link %2 for specimen '%3' (%4)"},
    // The identifiers' messages (core/updating, core/identification).
    {"prediction-rejected", "prediction rejected: %1"},
    {"update-rejected", "update rejected: %1"},
    {"bouc-wen-integration-failed", "Bouc-Wen integration failed (%1): %2"},
    {"state-not-advanced", "%1; z and e could not be advanced either: step skipped"},
    {"ukf-state-not-finite", "the state is not finite"},
    {"ukf-measurement-not-finite", "the measurement is not finite"},
    {"ukf-prediction-not-finite", "the predicted measurement is not finite"},
    {"ukf-innovation-not-pd", "the innovation covariance is not positive definite (check R)"},
    {"ukf-not-initialized", "the filter has not been initialized"},
    {"nelder-mead-failed", "Nelder-Mead fit failed: %1"},
    {"nelder-mead-kept",
     "Nelder-Mead trigger %1 kept the parameters (RMS %2 not improved, %3 evaluations, %4 ms)"},
    {"nelder-mead-refit",
     "Nelder-Mead trigger %1: RMS force error %2 -> %3 (%4 evaluations, %5 ms)"},
    {"measured-not-finite-skipped",
     "the measured deformation or force is not finite: step skipped"},
    // File readers (ground motion, configuration, record); "<file>: " or "<file> line <n>: "
    // before the problem.
    {"file-line", "%1 line %2: %3"},
    {"file-missing", "cannot open '%1': the file does not exist"},
    {"file-is-folder", "cannot open '%1': it is a folder, not a file"},
    {"file-not-regular", "cannot read '%1': not a regular file (a device, pipe or socket)"},
    {"file-unreadable", "cannot open '%1' for reading (permissions?)"},
    {"file-not-text", "'%1' is not a text file (binary data at byte %2)"},
    {"motion-empty-at2", "the file is empty (expected a PEER AT2 record)"},
    {"motion-empty", "the file is empty (no acceleration values)"},
    {"motion-no-data", "no data lines (only comments or blank lines)"},
    {"motion-unknown-empty",
     "the file is empty: expected an AT2 header ('NPTS=..., DT=...' on line 4), two columns "
     "(time, acceleration) or one column of values"},
    {"motion-unknown-no-data",
     "no data lines: expected an AT2 header ('NPTS=..., DT=...' on line 4), two columns (time, "
     "acceleration) or one column of values"},
    {"expected-number", "expected a number, found %1"},
    {"non-finite-value", "non-finite value %1"},
    {"dt-not-positive", "the time step dt must be > 0 s, got %1"},
    {"two-columns", "expected two columns (time, acceleration), found %1 value(s)"},
    {"one-sample", "only one sample: the time step cannot be determined"},
    {"time-not-increasing", "time must increase: %1 s follows %2 s"},
    {"non-uniform-step",
     "non-uniform time step: %1 s follows %2 s (step %3 s, mean step %4 s); a uniform step is "
     "required (tolerance 1e-6 relative)"},
    {"single-column-needs-dt",
     "a single column of acceleration values needs the time step dt, and none was given"},
    {"config-cannot-open", "cannot open the configuration file"},
    {"config-not-regular", "not a regular file (a folder, device, pipe or socket)"},
    {"config-not-json", "not valid JSON (%1)"},
    {"record-missing", "cannot be opened (no such file)"},
    {"record-not-hdf5", "not an HSMU record (not an HDF5 file)"},
    {"record-no-schema", "not an HSMU record (no schema_version attribute)"},
    {"record-damaged", "damaged record (%1)"},
    {"record-no-step", "the record holds no step"},
};

const Template* find(const char* code)
{
    for (const Template& t : kTemplates)
        if (std::strcmp(t.code, code) == 0)
            return &t;
    return nullptr;
}

bool placeholder(const char* p) { return p[0] == '%' && p[1] >= '1' && p[1] <= '9'; }

// Matches `text` from `pos` against the template from `t`; on success fills args (indexed).
bool match(const std::string& text, std::size_t pos, const char* t,
           std::vector<std::string>& args)
{
    while (*t && !placeholder(t)) {
        if (pos >= text.size() || text[pos] != *t)
            return false;
        ++pos;
        ++t;
    }
    if (!*t)
        return pos == text.size();
    const auto index = static_cast<std::size_t>(t[1] - '1');
    t += 2;
    if (args.size() <= index)
        args.resize(index + 1);
    // The shortest argument (at least one character) that lets the rest match.
    for (std::size_t end = pos + 1; end <= text.size(); ++end) {
        args[index] = text.substr(pos, end - pos);
        if (match(text, end, t, args))
            return true;
    }
    return false;
}
} // namespace

std::string reasonText(const char* code, const std::vector<std::string>& args)
{
    const Template* t = find(code);
    if (!t)
        return {};
    std::string out;
    for (const char* p = t->english; *p; ++p) {
        if (placeholder(p)) {
            const auto index = static_cast<std::size_t>(p[1] - '1');
            if (index < args.size())
                out += args[index];
            ++p;
        } else {
            out += *p;
        }
    }
    return out;
}

std::optional<CodedText> parseReason(const std::string& english)
{
    for (const Template& t : kTemplates) {
        std::vector<std::string> args;
        if (match(english, 0, t.english, args))
            return CodedText{t.code, std::move(args)};
    }
    return std::nullopt;
}

int reasonArgumentCount(const char* code)
{
    const Template* t = find(code);
    if (!t)
        return -1;
    int n = 0;
    for (const char* p = t->english; *p; ++p)
        if (placeholder(p))
            n = std::max(n, p[1] - '0');
    return n;
}

std::vector<std::string> reasonCodes()
{
    std::vector<std::string> codes;
    for (const Template& t : kTemplates)
        codes.emplace_back(t.code);
    return codes;
}

} // namespace hsmu
