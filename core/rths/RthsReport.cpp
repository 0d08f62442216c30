#include "core/rths/RthsReport.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace hsmu::rths {

double effectiveDelay(const RthsSettings& s, double f)
{
    const double w = 2.0 * M_PI * f;
    std::complex<double> t = closedLoopResponse(s, w);
    const auto& c = s.compensation;
    using T = CompensationSettings::Type;
    double extra = 0.0;
    if (c.type == T::Feedforward || c.type == T::Ats)
        t *= std::complex<double>(c.c0 - c.c2 * w * w, c.c1 * w);
    else if (c.type == T::Polynomial)
        extra = -(c.estimateDelay ? loopDelay(s, f) : c.delay);
    return -std::arg(t) / w + extra + s.forceDelay / s.rate;
}

Preflight preflight(const Partition& p, const RthsSettings& s)
{
    Preflight out;
    out.criticalDelay = criticalDelay(p);
    out.firstMode = naturalFrequencies(p.reference.m, p.reference.k)(0);
    out.loopDelay = effectiveDelay(s, out.firstMode);
    out.refused = out.loopDelay >= out.criticalDelay;
    out.flagged = !out.refused && out.loopDelay > 0.5 * out.criticalDelay;
    std::ostringstream o;
    o.precision(3);
    o << "loop delay " << out.loopDelay * 1e3 << " ms (after compensation, with the force's "
      << s.forceDelay << "-tick delay, at the first mode " << out.firstMode
      << " Hz) against the partition's critical delay " << out.criticalDelay * 1e3 << " ms";
    if (out.refused)
        o << ": the coupled loop would be unstable, refused";
    else if (out.flagged)
        o << ": above half of it, little margin";
    out.message = o.str();
    return out;
}

void writeRthsSteps(const std::string& path, const RthsRun& run)
{
    std::ofstream f(path);
    if (!f)
        throw std::runtime_error(path + ": cannot write the steps file");
    f << "time_s,desired_m,command_m,measured_m,force_N";
    for (Eigen::Index i = 0; i < run.hybrid.cols(); ++i)
        f << ",floor" << i + 1 << "_m";
    for (Eigen::Index i = 0; i < run.reference.cols(); ++i)
        f << ",reference" << i + 1 << "_m";
    f << '\n';
    char buf[64];
    const auto put = [&](double v) {
        std::snprintf(buf, sizeof buf, ",%.9g", v);
        f << buf;
    };
    for (std::size_t k = 0; k < run.time.size(); ++k) {
        std::snprintf(buf, sizeof buf, "%.9g", run.time[k]);
        f << buf;
        for (double v : {run.desired[k], run.command[k], run.measured[k], run.force[k]})
            put(v);
        for (Eigen::Index i = 0; i < run.hybrid.cols(); ++i)
            put(run.hybrid(Eigen::Index(k), i));
        for (Eigen::Index i = 0; i < run.reference.cols(); ++i)
            put(run.reference(Eigen::Index(k), i));
        f << '\n';
    }
    if (!f.flush())
        throw std::runtime_error(path + ": writing the steps file failed");
}

nlohmann::json rthsSummary(const RthsRun& run, const RthsSettings& s, const Preflight& pre)
{
    nlohmann::json j;
    j["ticks"] = run.time.size();
    j["rate_Hz"] = s.rate;
    j["finished"] = run.hold.empty();
    j["hold"] = run.hold;
    nlohmann::json crit;
    const char* unit[9] = {"ms", "%", "%", "%", "%", "%", "%", "%", "%"};
    for (int i = 0; i < 9; ++i)
        crit["J" + std::to_string(i + 1) + "_" + (unit[i][0] == 'm' ? "ms" : "percent")] = run.criteria.j[i];
    j["criteria"] = crit;
    j["frequencyEvaluation"] = {{"amplitude", run.frequency.amplitude},
                                {"delay_ms", run.frequency.delay},
                                {"frequency_Hz", run.frequency.frequency}};
    j["trackingIndicator_m2"] = run.trackingIndicator;
    j["peaks"] = {{"force_N", run.peakForce}, {"stroke_m", run.peakStroke}, {"velocity_m_per_s", run.peakVelocity}};
    j["preflight"] = {{"criticalDelay_ms", pre.criticalDelay * 1e3}, {"loopDelay_ms", pre.loopDelay * 1e3},
                      {"firstMode_Hz", pre.firstMode}, {"flagged", pre.flagged}, {"message", pre.message}};
    const auto& c = s.compensation;
    j["compensation"] = {{"type", compensationTypeName(c.type)}, {"lead", c.lead.enabled},
                         {"c0", c.c0}, {"c1_s", c.c1}, {"c2_s2", c.c2}, {"delay_s", c.delay}};
    j["controller"] = {{"kp", s.pid.kp}, {"ki_per_s", s.pid.ki}, {"kd_s", s.pid.kd}, {"tauD_s", s.pid.tauD}};
    const auto& p = s.plant;
    j["plant"] = {{"a1b0", p.a1b0}, {"a2", p.a2}, {"a3", p.a3}, {"b1", p.b1}, {"b2", p.b2},
                  {"me_kg", p.me}, {"ce_Ns_per_m", p.ce}, {"ke_N_per_m", p.ke}, {"g", p.g}};
    if (run.twin) { // the damper's twin: its updates with their ticks, its law at the end
        nlohmann::json updates = nlohmann::json::array();
        for (const UpdateEvent& e : run.updates) {
            nlohmann::json values = nlohmann::json::object();
            for (std::size_t i = 0; i < e.parameters.size() && i < e.applied.size(); ++i)
                values[e.parameters.name(i)] = e.applied[i];
            updates.push_back({{"tick", e.step}, {"time_s", e.time}, {"applied", e.ok},
                               {"message", e.message}, {"parameters", values}});
        }
        const MrDamper twin(*run.twin);
        nlohmann::json law = nlohmann::json::object();
        const auto names = twin.parameterNames();
        for (std::size_t i = 0; i < names.size(); ++i)
            law[names[i]] = twin.parameterValue(int(i));
        j["twin"] = {{"updates", updates}, {"parameters", law}};
    }
    return j;
}

} // namespace hsmu::rths
