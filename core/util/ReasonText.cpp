#include "core/util/ReasonText.h"

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

std::vector<std::string> reasonCodes()
{
    std::vector<std::string> codes;
    for (const Template& t : kTemplates)
        codes.emplace_back(t.code);
    return codes;
}

} // namespace hsmu
