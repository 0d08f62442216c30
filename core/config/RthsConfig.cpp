#include "core/config/RthsConfig.h"

#include "core/groundmotion/AccelerationUnit.h"
#include "core/groundmotion/GroundMotionReader.h"
#include "core/hysteresis/LawFactory.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <fstream>
#include <regex>

namespace hsmu {

using rths::CompensationSettings;

rths::Partition RthsConfig::partition() const
{
    const auto& p = settings.plant;
    return rths::partition(reference, rths::Specimen{specimenDof, p.me, p.ce, p.ke});
}

namespace {

Eigen::MatrixXd matrix(const JsonCursor& c, const std::string& key, Eigen::Index n)
{
    const JsonCursor rows = c.child(key);
    rows.requireArray();
    if (n > 0 && Eigen::Index(rows.size()) != n)
        rows.fail("", "a " + std::to_string(n) + " x " + std::to_string(n) + " matrix");
    const auto size = Eigen::Index(rows.size());
    Eigen::MatrixXd m(size, size);
    for (Eigen::Index i = 0; i < size; ++i) {
        const JsonCursor row = rows.at(std::size_t(i));
        row.requireArray();
        if (Eigen::Index(row.size()) != size)
            row.fail("", "a row of " + std::to_string(size) + " numbers (a square matrix)");
        for (Eigen::Index j = 0; j < size; ++j) {
            const auto& v = row.node()[std::size_t(j)];
            if (!v.is_number())
                row.at(std::size_t(j)).fail("", "a number");
            m(i, j) = v.get<double>();
        }
    }
    return m;
}

void parseStructure(const JsonCursor& s, RthsConfig& out)
{
    s.allowOnly({"benchmarkCase", "mass", "stiffness", "damping", "dampingRatio", "influence",
                 "specimenDof"});
    out.specimenDof = s.integer("specimenDof", 0, 0, 1000);
    if (s.has("benchmarkCase")) {
        out.benchmarkCase = s.integer("benchmarkCase", 1, 1, 4);
        out.reference = rths::benchmarkReference(out.benchmarkCase);
        return;
    }
    out.reference.k = matrix(s, "stiffness", 0);
    const auto n = out.reference.k.rows();
    out.reference.m = matrix(s, "mass", n);
    if (s.has("damping"))
        out.reference.c = matrix(s, "damping", n);
    else
        out.reference.c = rths::modalDamping(out.reference.m, out.reference.k,
                                             s.number("dampingRatio", 0.0));
    out.reference.iota = Eigen::VectorXd::Ones(n);
    if (s.has("influence")) {
        const JsonCursor v = s.child("influence");
        v.requireArray();
        if (Eigen::Index(v.size()) != n)
            v.fail("", "one number per DOF");
        for (Eigen::Index i = 0; i < n; ++i)
            out.reference.iota(i) = v.node()[std::size_t(i)].get<double>();
    }
    if (out.specimenDof >= n)
        s.fail("specimenDof", "a DOF of the structure (0 to " + std::to_string(n - 1) + ")");
}

/// An mrDamper law's parameters by name (LawFactory's names, checks and messages).
MrDamperParameters parseMrDamper(const JsonCursor& c)
{
    c.requireObject();
    std::map<std::string, double> values;
    for (const auto& [key, v] : c.node().items()) {
        if (!v.is_number())
            c.fail(key, "a number");
        values[key] = v.get<double>();
    }
    try {
        const auto law = makeLaw("mrDamper", values);
        return static_cast<const MrDamper&>(*law).parameters();
    } catch (const std::invalid_argument& e) {
        c.fail("", std::string("mrDamper parameters (") + e.what() + ")");
    }
    return {};
}

/// "damper": the MR damper in the specimen, its twin in the numerical substructure, the
/// parameter box of the twin's updates and the online identification (docs/rths.md).
void parseDamper(const JsonCursor& c, RthsConfig& out)
{
    c.allowOnly({"specimen", "twin", "twinDof", "forceNoise", "bounds", "identification"});
    auto& d = out.settings.damper;
    d.enabled = true;
    d.specimen = parseMrDamper(c.child("specimen"));
    d.twin = c.has("twin") ? parseMrDamper(c.child("twin")) : d.specimen;
    d.twinDof = c.integer("twinDof", 1, 0, 1000);
    if (d.twinDof >= out.reference.m.rows())
        c.fail("twinDof", "a DOF of the structure (0 to " + std::to_string(out.reference.m.rows() - 1) + ")");
    d.forceNoise = c.number("forceNoise", d.forceNoise);
    if (!(d.forceNoise >= 0.0))
        c.fail("forceNoise", "a noise level >= 0 N");
    if (c.has("bounds")) {
        const JsonCursor b = c.child("bounds");
        b.requireObject();
        const std::vector<std::string> names = MrDamper().parameterNames();
        for (const auto& [key, v] : b.node().items()) {
            if (std::find(names.begin(), names.end(), key) == names.end())
                b.fail(key, "an mrDamper parameter");
            if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
                !(v[0].get<double>() <= v[1].get<double>()))
                b.fail(key, "[lower, upper] with lower <= upper");
            d.box[key] = ParameterBounds{v[0].get<double>(), v[1].get<double>()};
        }
    }
    if (c.has("identification")) {
        const JsonCursor i = c.child("identification");
        i.allowOnly({"enabled", "decimation", "interval", "latency", "approve"});
        auto& s = out.identification;
        s.enabled = i.boolean("enabled", true);
        s.decimation = i.integer("decimation", s.decimation, 1, 1000);
        s.interval = i.number("interval", s.interval);
        s.latency = i.number("latency", s.latency);
        s.approve = i.boolean("approve", false);
        if (!(s.interval > 0.0 && s.latency >= 0.0))
            i.fail("", "interval > 0 s and latency >= 0 s");
    }
}

} // namespace

void parsePlantParameters(const JsonCursor& p, rths::PlantParameters& plant)
{
    p.allowOnly({"a1b0", "a2", "a3", "b1", "b2", "me", "ce", "ke", "g", "specimenDampingRatio"});
    plant.a1b0 = p.number("a1b0", plant.a1b0);
    plant.a2 = p.number("a2", plant.a2);
    plant.a3 = p.number("a3", plant.a3);
    plant.b1 = p.number("b1", plant.b1);
    plant.b2 = p.number("b2", plant.b2);
    plant.me = p.number("me", plant.me);
    plant.ke = p.number("ke", plant.ke);
    plant.g = p.number("g", plant.g);
    plant.ce = p.has("specimenDampingRatio")
                   ? rths::PlantParameters::specimenDamping(p.number("specimenDampingRatio"),
                                                            plant.ke, plant.me)
                   : p.number("ce", plant.ce);
    if (const std::string why = plant.validate(); !why.empty())
        p.fail("", why);
}

void parseLead(const JsonCursor& l, rths::LeadSettings& lead)
{
    l.allowOnly({"enabled", "gain", "zero", "pole"});
    lead.enabled = l.boolean("enabled", true);
    lead.gain = l.number("gain", lead.gain);
    lead.zero = l.number("zero", lead.zero);
    lead.pole = l.number("pole", lead.pole);
    if (!(lead.pole > 0.0 && lead.zero > 0.0 && lead.gain > 0.0))
        l.fail("", "a lead with positive gain, zero and pole [rad/s]");
}

void parsePidGains(const JsonCursor& c, rths::PidGains& pid)
{
    c.allowOnly({"kp", "ki", "kd", "tauD"});
    pid.kp = c.number("kp", pid.kp);
    pid.ki = c.number("ki", pid.ki);
    pid.kd = c.number("kd", pid.kd);
    pid.tauD = c.number("tauD", pid.tauD);
    if (pid.kd != 0.0 && !(pid.tauD > 0.0))
        c.fail("tauD", "a derivative filter time constant > 0 [s] with kd");
}

void parseActuatorLimits(const JsonCursor& l, rths::ActuatorLimits& limits)
{
    l.allowOnly({"stroke", "force", "velocity"});
    limits.stroke = l.number("stroke", limits.stroke);
    limits.force = l.number("force", limits.force);
    limits.velocity = l.number("velocity", limits.velocity);
    if (!(limits.stroke > 0.0 && limits.force > 0.0 && limits.velocity > 0.0))
        l.fail("", "positive stroke [m], force [N] and velocity [m/s] limits");
}

void parseServoActuator(const JsonCursor& a, rths::ServoActuatorSettings& s)
{
    a.allowOnly({"type", "rate", "plant", "controller", "lead", "quantum", "limits", "metresPerUnit"});
    s.rate = a.number("rate", s.rate);
    if (!(s.rate >= 100.0 && s.rate <= 100000.0))
        a.fail("rate", "a loop rate in Hz, 100 to 100000");
    if (a.has("plant"))
        parsePlantParameters(a.child("plant"), s.plant);
    if (a.has("controller"))
        parsePidGains(a.child("controller"), s.pid);
    if (a.has("lead"))
        parseLead(a.child("lead"), s.lead);
    if (a.has("limits"))
        parseActuatorLimits(a.child("limits"), s.limits);
    s.quantum = a.number("quantum", s.quantum);
    s.metresPerUnit = a.number("metresPerUnit", s.metresPerUnit);
    if (!(s.quantum >= 0.0))
        a.fail("quantum", "an A/D step >= 0 [m]");
    if (!(s.metresPerUnit > 0.0))
        a.fail("metresPerUnit", "actuator metres per unit of specimen deformation, > 0");
}

namespace {

void parseCompensation(const JsonCursor& c, CompensationSettings& s)
{
    c.allowOnly({"type", "order", "delay", "estimateDelay", "c0", "c1", "c2", "fitToLoop",
                 "window", "updateInterval", "filterFrequency", "maxC1", "maxC2", "maxChange",
                 "lead"});
    const std::string type = c.string("type", "none");
    if (!rths::parseCompensationType(type, s.type))
        c.fail("type", "none, polynomial, feedforward or ats");
    s.order = c.integer("order", s.order, 1, 5);
    s.delay = c.number("delay", s.delay);
    s.estimateDelay = c.boolean("estimateDelay", s.estimateDelay);
    s.c0 = c.number("c0", s.c0);
    s.c1 = c.number("c1", s.c1);
    s.c2 = c.number("c2", s.c2);
    s.fitToLoop = c.boolean("fitToLoop", s.fitToLoop);
    s.window = c.number("window", s.window);
    s.updateInterval = c.number("updateInterval", s.updateInterval);
    s.filterFrequency = c.number("filterFrequency", s.filterFrequency);
    s.maxC1 = c.number("maxC1", s.maxC1);
    s.maxC2 = c.number("maxC2", s.maxC2);
    s.maxChange = c.number("maxChange", s.maxChange);
    if (!(s.delay >= 0.0 && s.delay < 0.1))
        c.fail("delay", "a delay in seconds, 0 to 0.1");
    if (!(s.window > 0.0 && s.updateInterval > 0.0 && s.filterFrequency > 0.0))
        c.fail("window", "positive window, updateInterval [s] and filterFrequency [Hz]");
    if (c.has("lead"))
        parseLead(c.child("lead"), s.lead);
}

} // namespace

RthsConfig parseRthsConfig(const nlohmann::json& document, const std::string& file)
{
    const JsonCursor root(document, file);
    root.requireObject();
    RthsConfig out;
    out.name = root.string("name", "RTHS");
    out.raw = document;
    const JsonCursor r = root.child("rths");
    r.allowOnly({"rate", "structure", "plant", "limits", "sensors", "controller", "compensation",
                 "forceDelay", "groundMotion", "holdAfterMisses", "damper"});
    auto& s = out.settings;
    s.rate = r.number("rate", 4096.0);
    if (!(s.rate >= 100.0 && s.rate <= 100000.0))
        r.fail("rate", "a loop rate in Hz, 100 to 100000");
    s.forceDelay = r.integer("forceDelay", 1, 0, 100);
    out.holdAfterMisses = r.integer("holdAfterMisses", 10, 0, 1000000);
    if (r.has("plant"))
        parsePlantParameters(r.child("plant"), s.plant);
    parseStructure(r.child("structure"), out);
    if (r.has("limits"))
        parseActuatorLimits(r.child("limits"), s.limits);
    if (r.has("sensors")) {
        const JsonCursor n = r.child("sensors");
        n.allowOnly({"noise", "displacementNoise", "forceNoise", "quantum", "seed"});
        s.sensors.noise = n.boolean("noise", s.sensors.noise);
        s.sensors.displacementNoise = n.number("displacementNoise", s.sensors.displacementNoise);
        s.sensors.forceNoise = n.number("forceNoise", s.sensors.forceNoise);
        s.sensors.quantum = n.number("quantum", s.sensors.quantum);
        s.sensors.seed = std::uint64_t(n.integer("seed", 1, 0, 2147483647));
        if (!(s.sensors.displacementNoise >= 0.0 && s.sensors.forceNoise >= 0.0 && s.sensors.quantum >= 0.0))
            n.fail("", "noise levels and quantum that are zero or positive");
    }
    if (r.has("controller"))
        parsePidGains(r.child("controller"), s.pid);
    if (r.has("compensation"))
        parseCompensation(r.child("compensation"), s.compensation);
    if (r.has("damper"))
        parseDamper(r.child("damper"), out);
    if (r.has("groundMotion")) {
        const JsonCursor g = r.child("groundMotion");
        g.allowOnly({"file", "scale", "unit"});
        out.groundMotionFile = g.string("file", "");
        out.groundMotionScale = g.number("scale", 1.0);
        out.groundMotionUnit = g.string("unit", "m/s^2");
        if (!parseAccelerationUnit(out.groundMotionUnit))
            g.fail("unit", "an acceleration unit: g, m/s^2 or cm/s^2");
    }
    return out;
}

RthsConfig loadRthsConfig(const std::string& path)
{
    if (auto generated = rthsBenchmarkDocument(path))
        return parseRthsConfig(*generated, "preset " + path);
    std::ifstream in(path);
    if (!in)
        throw ConfigError(path + ": cannot open the file (nor is it a preset: rths-benchmark-case-1 to -4)");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in, nullptr, true, false);
    } catch (const nlohmann::json::exception& e) {
        throw ConfigError(path + ": not valid JSON: " + e.what());
    }
    return parseRthsConfig(doc, path);
}

std::optional<nlohmann::json> rthsBenchmarkDocument(const std::string& name)
{
    static const std::regex pattern("rths-benchmark-case-([1-4])");
    std::smatch m;
    if (!std::regex_match(name, m, pattern))
        return std::nullopt;
    const int c = std::stoi(m[1]);
    return nlohmann::json{
        {"name", "RTHS benchmark, case " + std::to_string(c) + " (Silva et al. 2020)"},
        {"rths",
         {{"rate", 4096},
          {"structure", {{"benchmarkCase", c}, {"specimenDof", 0}}},
          {"plant", nlohmann::json::object()},
          {"limits", {{"stroke", 0.007}, {"force", 8900}, {"velocity", 0.3}}},
          {"sensors", {{"noise", true}, {"displacementNoise", 1.6e-5}, {"forceNoise", 2.2}, {"quantum", 3.81e-6}, {"seed", 1}}},
          {"controller", {{"kp", 2.0}, {"ki", 95.0}}},
          {"compensation", {{"type", "none"}, {"lead", {{"enabled", true}}}}},
          {"forceDelay", 1},
          {"groundMotion",
           {{"file", "../shared/data/rths-benchmark/elcentro_benchmark.txt"}, {"scale", 0.4}, {"unit", "m/s^2"}}}}}};
}

GroundMotion loadRthsGroundMotion(const RthsConfig& cfg, const std::string& file, double scale)
{
    const std::string path = file.empty() ? cfg.groundMotionFile : file;
    if (path.empty())
        throw std::runtime_error("no ground motion: the configuration names no rths.groundMotion.file");
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw std::runtime_error(path + ": the ground-motion record does not exist");
    const auto unit = parseAccelerationUnit(cfg.groundMotionUnit); // checked by the parser
    return readGroundMotion(path, GroundMotionFormat::Auto, unit).scaled(scale);
}

} // namespace hsmu
