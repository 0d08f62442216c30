#include "core/config/ConfigLoader.h"
#include "core/config/ConfigUnits.h"
#include "core/config/JsonNesting.h"
#include "core/config/Link2dConfig.h"
#include "core/config/NumericalSite.h"
#include "core/config/RecordConfig.h"
#include "core/config/RthsConfig.h"
#include "core/config/UpdatingConfig.h"

#include "core/hysteresis/HysteresisLaw.h"
#include "core/hysteresis/LawFactory.h"
#include "core/util/InputLimits.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <algorithm>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <sstream>
#include <unordered_set>

namespace hsmu {

MaterialSpec parseMaterial(const JsonCursor& c)
{
    c.requireObject();
    MaterialSpec m;
    m.law = c.string("law");
    for (auto it = c.node().begin(); it != c.node().end(); ++it) {
        if (it.key() == "law")
            continue;
        m.params[it.key()] = c.number(it.key());
    }
    try { // validate now, so the message carries the field path
        m.law = makeLaw(m.law, m.params)->lawName(); // the canonical name ("mr-damper": mrDamper)
    } catch (const std::exception& e) {
        c.fail("", e.what());
    }
    return m;
}

SafetyLimits parseLimits(const JsonCursor& c)
{
    c.allowOnly({"deformation", "force", "increment"});
    SafetyLimits l;
    l.maxDeformation = c.number("deformation", l.maxDeformation);
    l.maxForce = c.number("force", l.maxForce);
    l.maxIncrement = c.number("increment", l.maxIncrement);
    for (const char* k : {"deformation", "force", "increment"})
        if (c.has(k) && !(c.number(k) > 0.0))
            c.fail(k, "expected a positive limit");
    return l;
}

int parseDof(const JsonCursor& c, const nlohmann::json& v, const std::vector<DofSpec>& dofs,
             const std::string& key)
{
    if (v.is_number_integer()) {
        // Compared as 64-bit: 4294967297 must not become DOF 1.
        const bool neg = !v.is_number_unsigned() && v.get<std::int64_t>() < 0;
        if (neg || v.get<std::uint64_t>() >= dofs.size())
            c.fail(key, "DOF index " + v.dump() + " out of range 0.." +
                            std::to_string(dofs.size() - 1));
        return static_cast<int>(v.get<std::uint64_t>());
    }
    if (v.is_string()) {
        for (std::size_t i = 0; i < dofs.size(); ++i)
            if (dofs[i].name == v.get<std::string>())
                return static_cast<int>(i);
        c.fail(key, "no DOF named '" + v.get<std::string>() + "'");
    }
    c.fail(key, "expected a DOF name or index");
}

namespace {

std::string fmt(double x)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%g", x);
    return buf;
}

} // namespace

ActuatorModel parseActuatorModel(const JsonCursor& a)
{
    ActuatorModel m;
    const std::string type = a.string("type", "ideal");
    if (type != "servoHydraulic")
        a.allowOnly({"type", "timeConstant", "delay"});
    if (type == "servoHydraulic") {
        m.type = ActuatorModel::Type::ServoHydraulic;
        parseServoActuator(a, m.servo); // SI units, docs/rths.md
    } else if (type == "ideal")
        m.type = ActuatorModel::Type::Ideal;
    else if (type == "lag") {
        m.type = ActuatorModel::Type::Lag;
        m.timeConstant = a.number("timeConstant");
        if (!(m.timeConstant > 0.0) || m.timeConstant > limits::kMaxActuatorTimeConstant)
            a.fail("timeConstant", "expected a time constant in (0, " +
                                       fmt(limits::kMaxActuatorTimeConstant) + "] s");
    } else if (type == "delay") {
        m.type = ActuatorModel::Type::Delay;
        m.delay = a.number("delay");
        if (m.delay < 0.0 || m.delay > limits::kMaxActuatorDelay)
            a.fail("delay", "expected a delay in [0, " + fmt(limits::kMaxActuatorDelay) + "] s");
    } else
        a.fail("type", "expected 'ideal', 'lag', 'delay' or 'servoHydraulic', found '" + type + "'");
    return m;
}

namespace {

SpecimenSpec parseSpecimen(const JsonCursor& c)
{
    c.allowOnly({"material", "forceNoiseStd", "deformationNoiseStd", "seed", "actuator",
                 "fracture", "interlock"});
    SpecimenSpec s;
    s.trueMaterial = parseMaterial(c.child("material"));
    auto& o = s.options;
    o.forceNoiseStd = c.number("forceNoiseStd", 0.0);
    o.deformationNoiseStd = c.number("deformationNoiseStd", 0.0);
    if (o.forceNoiseStd < 0.0)
        c.fail("forceNoiseStd", "expected a standard deviation >= 0");
    if (o.deformationNoiseStd < 0.0)
        c.fail("deformationNoiseStd", "expected a standard deviation >= 0");
    o.seed = static_cast<std::uint64_t>(c.integer("seed", 1, 0, std::numeric_limits<int>::max()));
    if (c.has("actuator"))
        o.actuator = parseActuatorModel(c.child("actuator"));
    if (c.has("fracture")) {
        const JsonCursor f = c.child("fracture");
        f.allowOnly({"atCumulativeDeformation", "atTime", "strengthLoss"});
        o.fracture.atCumulativeDeformation =
            f.number("atCumulativeDeformation", o.fracture.atCumulativeDeformation);
        o.fracture.atTime = f.number("atTime", o.fracture.atTime);
        o.fracture.strengthLoss = f.number("strengthLoss", 0.5);
        if (!o.fracture.enabled())
            f.fail("", "expected atCumulativeDeformation or atTime");
        if (o.fracture.strengthLoss < 0.0 || o.fracture.strengthLoss > 1.0)
            f.fail("strengthLoss", "expected a fraction in [0, 1]");
    }
    if (c.has("interlock"))
        o.interlock = parseLimits(c.child("interlock"));
    return s;
}

ElementSpec parseElement(const JsonCursor& c, const std::vector<DofSpec>& dofs)
{
    if (c.has("type") && c.node().at("type") == "link2d")
        return parseLink2dElement(c, dofs); // Link2dConfig.h
    c.allowOnly({"name", "type", "dof", "dofs", "height", "ei", "material", "experimental",
                 "specimen", "limits", "numericalSite"});
    ElementSpec e;
    e.name = c.string("name");
    e.type = c.string("type");
    if (e.type == "truss") {
        const JsonCursor d = c.child("dofs");
        if (d.size() != 2)
            d.fail("", "expected two DOFs [from, to]");
        e.dofs = {parseDof(c, d.node()[0], dofs, "dofs"), parseDof(c, d.node()[1], dofs, "dofs")};
    } else if (e.type == "lateralSpring" || e.type == "rotationalBaseSpring") {
        if (!c.has("dof"))
            c.fail("dof", "missing (expected the DOF the element acts on)");
        e.dofs = {parseDof(c, c.node().at("dof"), dofs, "dof")};
    } else {
        c.fail("type", "expected 'lateralSpring', 'rotationalBaseSpring', 'truss' or 'link2d', found '" +
                           e.type + "'");
    }
    if (e.type == "rotationalBaseSpring") {
        e.height = c.number("height");
        if (!(e.height > 0.0))
            c.fail("height", "expected a column height > 0 m");
        if (c.has("ei")) {
            e.ei = c.number("ei");
            if (!(e.ei > 0.0))
                c.fail("ei", "expected EI > 0 kN m^2 (omit it for a rigid column)");
        }
    }
    e.material = parseMaterial(c.child("material"));
    e.experimental = c.boolean("experimental", false);
    if (e.experimental) {
        if (std::isfinite(e.ei))
            c.fail("ei", "a specimen's column is part of the specimen: omit ei");
        e.specimen = parseSpecimen(c.child("specimen"));
        if (c.has("limits"))
            e.limits = parseLimits(c.child("limits"));
    } else if (c.has("specimen")) {
        c.fail("specimen", "only allowed with \"experimental\": true");
    }
    if (c.has("numericalSite")) {
        if (e.experimental)
            c.fail("numericalSite", "only for numerical elements (a specimen has a controller)");
        if (std::isfinite(e.ei))
            c.fail("numericalSite", "not with a flexible column (ei): its spring is evaluated "
                                    "several times per step, the site once");
        e.numericalSite = c.string("numericalSite");
        if (std::string why = numericalSiteProblem(e.numericalSite); !why.empty())
            c.fail("numericalSite", why);
    }
    return e;
}

} // namespace

TestConfig parseConfig(const nlohmann::json& document, const std::string& sourceName)
{
    // Values in the console's units from here on (the "units" block, ConfigUnits.h); cfg.raw
    // keeps the document as written.
    const nlohmann::json converted = toConsoleUnits(document, sourceName);
    const JsonCursor root(converted, sourceName);
    // "controller": the link fields here (LinkConfig); the rest is hsmu-controller's
    // (comms/controller/ControllerSettings.h).
    root.allowOnly({"name", "description", "units", "structure", "groundMotion", "analysis",
                    "controller", "sites", "updating", "tls", "record"});
    TestConfig cfg;
    cfg.sourcePath = sourceName;
    cfg.raw = document;
    cfg.name = root.string("name", "unnamed test");
    cfg.description = root.string("description", "");
    cfg.link = parseLinkSpec(
        root, sourceName.empty() ? std::string()
                                 : std::filesystem::path(sourceName).parent_path().string());

    const JsonCursor s = root.child("structure");
    s.allowOnly({"dofs", "equalDofs", "damping", "elements"});
    const JsonCursor dofs = s.child("dofs");
    if (dofs.size() == 0)
        dofs.fail("", "expected at least one DOF");
    for (std::size_t i = 0; i < dofs.size(); ++i) {
        const JsonCursor d = dofs.at(i);
        d.allowOnly({"name", "mass", "influence"});
        DofSpec spec{d.string("name", "DOF " + std::to_string(i + 1)), d.number("mass")};
        if (!(spec.mass > 0.0))
            d.fail("mass", "expected a mass > 0 t");
        spec.influence = d.number("influence", 1.0);
        if (!std::isfinite(spec.influence))
            d.fail("influence", "expected a finite number (1: shaken by the record, 0: not)");
        cfg.dofs.push_back(spec);
    }
    if (s.has("equalDofs")) {
        const JsonCursor eq = s.child("equalDofs");
        for (std::size_t i = 0; i < eq.size(); ++i) {
            const JsonCursor q = eq.at(i);
            q.allowOnly({"master", "slave"});
            if (!q.has("master") || !q.has("slave"))
                q.fail("", "expected {\"master\": DOF, \"slave\": DOF}");
            cfg.equalDofs.emplace_back(parseDof(q, q.node().at("master"), cfg.dofs, "master"),
                                       parseDof(q, q.node().at("slave"), cfg.dofs, "slave"));
        }
    }
    if (s.has("damping")) {
        const JsonCursor d = s.child("damping");
        d.allowOnly({"ratio", "modes", "a0", "a1"});
        if (d.has("ratio")) {
            cfg.damping.kind = DampingSpec::Kind::ModalRatio;
            cfg.damping.ratio = d.number("ratio");
            if (cfg.damping.ratio < 0.0 || cfg.damping.ratio >= 1.0)
                d.fail("ratio", "expected a damping ratio in [0, 1)");
            if (d.has("modes")) {
                const JsonCursor m = d.child("modes");
                if (m.size() != 2 || !m.node()[0].is_number_integer() ||
                    !m.node()[1].is_number_integer())
                    m.fail("", "expected two mode numbers >= 1, e.g. [1, 2]");
                cfg.damping.modeI = m.checkedInteger(m.node()[0], "[0]", 1, 100000);
                cfg.damping.modeJ = m.checkedInteger(m.node()[1], "[1]", 1, 100000);
            }
        } else {
            cfg.damping.kind = DampingSpec::Kind::Coefficients;
            cfg.damping.a0 = d.number("a0", 0.0);
            cfg.damping.a1 = d.number("a1", 0.0);
        }
    }
    const JsonCursor elements = s.child("elements");
    // A set, not a scan of the earlier names: 10,000 elements cost 50 million string
    // comparisons that way (issue 27, docs/benchmarks.md).
    std::unordered_set<std::string> elementNames;
    for (std::size_t i = 0; i < elements.size(); ++i) {
        cfg.elements.push_back(parseElement(elements.at(i), cfg.dofs));
        if (!elementNames.insert(cfg.elements.back().name).second)
            elements.at(i).fail("name", "duplicate element name '" +
                                            cfg.elements.back().name + "'");
    }
    cfg.sites = parseSites(
        root, sourceName.empty() ? std::string()
                                 : std::filesystem::path(sourceName).parent_path().string(),
        cfg.link, cfg.elements);

    if (root.has("groundMotion")) {
        const JsonCursor g = root.child("groundMotion");
        g.allowOnly({"builtin", "file", "format", "units", "dt", "scale", "seed"});
        auto& gm = cfg.groundMotion;
        gm.builtin = g.string("builtin", gm.builtin);
        gm.file = g.string("file", "");
        gm.format = g.string("format", gm.format);
        gm.units = g.string("units", "");
        gm.dt = g.number("dt", 0.0);
        if (g.has("dt") && (gm.dt < limits::kMinDt || gm.dt > limits::kMaxDt))
            g.fail("dt", "expected a time step in [" + fmt(limits::kMinDt) + ", " +
                             fmt(limits::kMaxDt) + "] s");
        gm.scale = g.number("scale", 1.0);
        gm.seed = static_cast<unsigned>(
            g.integer("seed", static_cast<int>(gm.seed), 0, std::numeric_limits<int>::max()));
        if (gm.file.empty() && gm.builtin != "synthetic")
            g.fail("builtin", "expected \"synthetic\" (the only built-in record)");
        if (gm.format != "auto" && gm.format != "at2" && gm.format != "time-acc" &&
            gm.format != "single")
            g.fail("format", "expected auto, at2, time-acc or single");
    }
    if (root.has("analysis")) {
        const JsonCursor a = root.child("analysis");
        a.allowOnly({"integrator", "alpha", "dt", "duration", "allowUnstable"});
        auto& an = cfg.analysis;
        an.integrator = a.string("integrator", an.integrator);
        if (an.integrator != "explicitNewmark" && an.integrator != "alphaOS")
            a.fail("integrator", "expected 'explicitNewmark' or 'alphaOS'");
        an.alpha = a.number("alpha", an.alpha);
        if (an.alpha < -1.0 / 3.0 - 1e-12 || an.alpha > 0.0)
            a.fail("alpha", "expected alpha in [-1/3, 0]");
        an.dt = a.number("dt", an.dt);
        if (!(an.dt >= limits::kMinDt && an.dt <= limits::kMaxDt))
            a.fail("dt", "expected a time step in [" + fmt(limits::kMinDt) + ", " +
                             fmt(limits::kMaxDt) + "] s");
        an.duration = a.number("duration", 0.0);
        if (an.duration < 0.0 || an.duration > limits::kMaxDuration)
            a.fail("duration", "expected a duration in [0, " + fmt(limits::kMaxDuration) +
                                   "] s (0: the whole ground motion)");
        if (an.duration / an.dt > double(limits::kMaxSteps))
            a.fail("duration", "duration / dt = " + fmt(an.duration / an.dt) +
                                   " steps, more than " + fmt(double(limits::kMaxSteps)));
        an.allowUnstable = a.boolean("allowUnstable", false);
    }
    if (root.has("updating"))
        cfg.updating = parseUpdating(root.child("updating"), cfg);
    cfg.record = parseRecordSection(root, cfg);
    return cfg;
}

TestConfig loadConfigFile(const std::string& path)
{
    std::error_code ec;
    if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw ConfigError(path + ": not a regular file (a folder, device, pipe or socket)");
    if (const auto size = std::filesystem::file_size(path, ec);
        !ec && size > limits::kMaxTextFileBytes)
        throw ConfigError(path + ": too large for a configuration (" + std::to_string(size) +
                          " bytes)");
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw ConfigError(path + ": cannot open the configuration file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (const auto at = firstTooDeep(text, limits::kMaxJsonDepth))
        throw ConfigError(
            path + " line " +
            std::to_string(1 + std::count(text.begin(),
                                          text.begin() + static_cast<std::ptrdiff_t>(*at), '\n')) +
            ": arrays and objects nested deeper than " + std::to_string(limits::kMaxJsonDepth) +
            " levels");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::exception& e) {
        // parse_error carries the byte offset; out_of_range (a number like 1e999 that
        // overflows a double) only the token: find it in the text to name the line.
        std::string where;
        std::size_t at = std::string::npos;
        if (const auto* pe = dynamic_cast<const nlohmann::json::parse_error*>(&e))
            at = pe->byte > 0 ? pe->byte - 1 : 0;
        const std::string what = e.what();
        if (const auto q = what.find("parsing '"); at == std::string::npos && q != std::string::npos) {
            const auto q2 = what.find('\'', q + 9);
            if (q2 != std::string::npos)
                at = text.find(what.substr(q + 9, q2 - q - 9));
        }
        if (at != std::string::npos && at <= text.size())
            where = " line " + std::to_string(1 + std::count(text.begin(), text.begin() +
                                                                 static_cast<std::ptrdiff_t>(at),
                                                             '\n'));
        throw ConfigError(path + where + ": not valid JSON (" + what + ")");
    }
    return parseConfig(doc, path);
}

} // namespace hsmu
