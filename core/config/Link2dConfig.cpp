#include "core/config/Link2dConfig.h"

#include "core/config/ConfigLoader.h"
#include "core/config/SetupConfig.h"
#include "core/experimental/setup/SetupScript.h"
#include "core/experimental/CantileverColumn.h"
#include "core/hysteresis/LawFactory.h"
#include "core/structure/Link2dKinematics.h"

#include <cmath>

namespace hsmu {

namespace {

// "forceSchedule": [[t [s], F [kN]], ...], t strictly increasing (ActuatorChannel.h, eq. F1).
std::vector<std::array<double, 2>> parseForceSchedule(const JsonCursor& c)
{
    const JsonCursor p = c.child("forceSchedule");
    p.requireArray();
    std::vector<std::array<double, 2>> out;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const auto& v = p.node()[k];
        if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
            c.fail("forceSchedule", "point " + std::to_string(k + 1) +
                                        ": expected [t, F] (time [s], force [kN])");
        out.push_back({v[0].get<double>(), v[1].get<double>()});
    }
    if (out.empty())
        c.fail("forceSchedule", "expected at least one point [t, F]");
    if (const std::string why = forceScheduleProblem(out); !why.empty())
        c.fail("forceSchedule", why);
    return out;
}

// A numerical basic DOF: a material, a held force (constant or scheduled), or nothing.
Link2dBasicSpec parseBasic(const JsonCursor& c)
{
    c.allowOnly({"material", "heldForce", "forceSchedule"});
    Link2dBasicSpec b;
    if (c.has("material") && (c.has("heldForce") || c.has("forceSchedule")))
        c.fail(c.has("heldForce") ? "heldForce" : "forceSchedule",
               "either a material or a held force, not both");
    if (c.has("heldForce") && c.has("forceSchedule"))
        c.fail("forceSchedule", "a held force is \"heldForce\" (constant) or \"forceSchedule\" "
                                "([[t, F], ...]), not both");
    if (c.has("material")) {
        b.hasMaterial = true;
        b.material = parseMaterial(c.child("material"));
    }
    b.heldForce = c.number("heldForce", 0.0);
    if (c.has("forceSchedule"))
        b.forceSchedule = parseForceSchedule(c);
    return b;
}

// "specimen": {"type": "cantileverColumn", "hinge": {...}, "axial": {...}, "ei": EI}.
WholeSpecimenSpec parseWholeSpecimen(const JsonCursor& c)
{
    c.allowOnly({"type", "hinge", "axial", "ei"});
    const std::string type = c.string("type");
    if (type != "cantileverColumn")
        c.fail("type", "expected 'cantileverColumn', found '" + type + "'");
    WholeSpecimenSpec w;
    w.hinge = parseMaterial(c.child("hinge"));
    w.axial = parseMaterial(c.child("axial"));
    w.ei = c.number("ei");
    if (!(w.ei > 0.0) || !std::isfinite(w.ei))
        c.fail("ei", "expected the column's EI > 0 kN m^2 (finite: a rigid column would fix the "
                     "top rotation to the hinge's)");
    return w;
}

ActuatorSpec parseActuator(const JsonCursor& c, bool whole)
{
    c.allowOnly({"name", "control", "force", "forceSchedule", "limits", "material",
                 "initialStiffness", "actuator"});
    ActuatorSpec a;
    a.channel.name = c.string("name");
    const std::string mode = c.string("control", "displacement");
    if (mode == "force") {
        a.channel.mode = ActuatorMode::Force;
        if (c.has("force") == c.has("forceSchedule"))
            c.fail("force", "a force-controlled actuator takes \"force\" (constant) or "
                            "\"forceSchedule\" ([[t, F], ...]), one of them");
        if (c.has("force"))
            a.channel.heldForce = c.number("force");
        else
            a.channel.forceSchedule = parseForceSchedule(c);
    } else if (mode == "displacement") {
        for (const char* k : {"force", "forceSchedule"})
            if (c.has(k))
                c.fail(k, "only for a force-controlled actuator (\"control\": \"force\")");
    } else {
        c.fail("control", "expected 'displacement' or 'force', found '" + mode + "'");
    }
    if (c.has("limits"))
        a.channel.limits = parseLimits(c.child("limits"));
    // A schedule is linear between its points: its largest |F| is at one of them.
    for (const auto& [t, f] : a.channel.forceSchedule)
        if (auto why = a.channel.limits.violationOfForce(f))
            c.fail("forceSchedule", "actuator '" + a.channel.name + "' at t = " +
                                        std::to_string(t) + " s: " + *why);
    if (c.has("actuator")) {
        a.model = parseActuatorModel(c.child("actuator"));
        if (a.channel.mode == ActuatorMode::Force &&
            a.model.type == ActuatorModel::Type::ServoHydraulic)
            c.child("actuator").fail("type", "a force-controlled actuator takes 'ideal', 'lag' "
                                             "or 'delay' (servoHydraulic is a displacement servo)");
    }
    if (whole) {
        if (c.has("material"))
            c.fail("material", "the lab simulates the whole specimen (\"specimen\"): an "
                               "actuator takes no material");
    } else {
        a.material = parseMaterial(c.child("material"));
    }
    if (c.has("initialStiffness")) {
        a.channel.initialStiffness = c.number("initialStiffness");
        if (!(a.channel.initialStiffness >= 0.0) || !std::isfinite(a.channel.initialStiffness))
            c.fail("initialStiffness", "expected a stiffness >= 0 kN/m");
    } else if (a.channel.mode == ActuatorMode::Displacement && !whole) {
        // with a whole specimen: from the specimen, setWholeSpecimenStiffness
        a.channel.initialStiffness = makeLaw(a.material.law, a.material.params)->initialTangent();
    }
    return a;
}

} // namespace

std::unique_ptr<SpecimenBehindSetup> buildWholeSpecimen(const std::string& element,
                                                        const Link2dSpec& s)
{
    const WholeSpecimenSpec& w = *s.wholeSpecimen;
    std::string error;
    auto setup = buildLink2dSetup(s, error);
    if (!setup)
        throw ConfigError("element '" + element + "': setup: " + error);
    std::vector<ActuatorMode> modes;
    for (const ActuatorSpec& a : s.actuators)
        modes.push_back(a.channel.mode);
    const std::string where = "element '" + element + "' specimen";
    try {
        auto column = std::make_unique<CantileverColumn>(
            makeLaw(w.axial.law, w.axial.params), makeLaw(w.hinge.law, w.hinge.params), s.length,
            w.ei);
        return std::make_unique<SpecimenBehindSetup>(std::move(setup), std::move(column),
                                                     std::move(modes));
    } catch (const std::exception& x) {
        throw ConfigError(where + ": " + x.what());
    }
}

namespace {

void setWholeSpecimenStiffness(const JsonCursor& c, const std::string& element, Link2dSpec& s,
                               const JsonCursor& acts)
{
    try {
        const auto whole = buildWholeSpecimen(element, s);
        for (std::size_t i = 0; i < s.actuators.size(); ++i) {
            ActuatorChannelSpec& ch = s.actuators[i].channel;
            if (acts.at(i).has("initialStiffness") || ch.mode != ActuatorMode::Displacement)
                continue;
            ch.initialStiffness = whole->channelStiffness(static_cast<int>(i), true);
        }
    } catch (const ConfigError& x) {
        c.fail("specimen", x.what());
    }
}

} // namespace

std::unique_ptr<ExperimentalSetup> buildLink2dSetup(const Link2dSpec& s, std::string& error)
{
    SetupsByTag setups;
    if (!parseSetupScript(s.setupScript, setups, error))
        return nullptr;
    if (setups.size() != 1) {
        error = "defines " + std::to_string(setups.size()) +
                " top-level setups, expected one (sub-setups go into an Aggregator)";
        return nullptr;
    }
    return std::move(setups.begin()->second);
}

ElementSpec parseLink2dElement(const JsonCursor& c, const std::vector<DofSpec>& dofs)
{
    c.allowOnly({"name", "type", "dofs", "length", "angle", "geometry", "basic", "primary",
                 "experimental", "setup", "actuators", "specimen"});
    ElementSpec e;
    e.name = c.string("name");
    e.type = "link2d";
    Link2dSpec s;
    const JsonCursor d = c.child("dofs");
    if (!d.node().is_array() || d.size() != 6)
        c.fail("dofs", "expected six DOFs [xi, yi, thetai, xj, yj, thetaj], null for a support");
    for (int k = 0; k < 6; ++k) {
        const auto& v = d.node()[k];
        s.dofs[k] = v.is_null() ? -1 : parseDof(c, v, dofs, "dofs");
        if (s.dofs[k] >= 0)
            e.dofs.push_back(s.dofs[k]);
    }
    if (e.dofs.empty())
        c.fail("dofs", "every DOF is a support: the element would do nothing");
    s.length = c.number("length");
    if (!(s.length > 0.0) || !std::isfinite(s.length))
        c.fail("length", "expected a length > 0 m");
    s.angle = c.number("angle", 90.0);
    if (!std::isfinite(s.angle))
        c.fail("angle", "expected an angle in degrees");
    const std::string geometry = c.string("geometry", "linear");
    if (!link2dTransformationFromName(geometry, s.transformation))
        c.fail("geometry", "expected 'linear' (small displacements) or 'corotational' (large "
                           "displacements), found '" + geometry + "'");
    s.primary = c.integer("primary", 1, 0, 2);
    e.experimental = c.boolean("experimental", false);
    if (e.experimental) {
        if (c.has("basic"))
            c.fail("basic", "a specimen's basic forces come from its actuators: omit basic");
        const JsonCursor st = c.child("setup");
        // An expSetup line, or the same as a type and OpenFresco's parameters (SetupConfig.h).
        const char* field = st.has("script") ? "script" : "type";
        if (st.has("script")) {
            st.allowOnly({"script"});
            s.setupScript = st.string("script");
        } else {
            s.setupScript = setupScriptOf(st);
        }
        std::string error;
        auto setup = buildLink2dSetup(s, error);
        if (!setup)
            st.fail(field, error);
        if (setup->basicSize() != 3)
            st.fail(field, setup->typeName() + " serves " + std::to_string(setup->basicSize()) +
                                  " basic DOFs, a link2d element has 3 (axial, shear, rotation): "
                                  "-sizeTrialOut 3 3");
        if (c.has("specimen"))
            s.wholeSpecimen = parseWholeSpecimen(c.child("specimen"));
        const JsonCursor acts = c.child("actuators");
        acts.requireArray();
        for (std::size_t i = 0; i < acts.size(); ++i)
            s.actuators.push_back(parseActuator(acts.at(i), s.wholeSpecimen.has_value()));
        if (int(s.actuators.size()) != setup->actuatorCount())
            c.fail("actuators", setup->typeName() + " has " +
                                    std::to_string(setup->actuatorCount()) + " actuators, " +
                                    std::to_string(s.actuators.size()) + " given");
        if (s.wholeSpecimen) // K0: the stiffness each actuator sees of the specimen at rest
            setWholeSpecimenStiffness(c, e.name, s, acts);
    } else {
        for (const char* k : {"setup", "actuators", "specimen"})
            if (c.has(k))
                c.fail(k, "only with \"experimental\": true");
        const JsonCursor b = c.child("basic");
        if (!b.node().is_array() || b.size() != 3)
            c.fail("basic", "expected three basic DOFs [axial, shear, rotation]");
        for (int k = 0; k < 3; ++k)
            s.basic[k] = parseBasic(b.at(k));
        if (!s.basic[s.primary].hasMaterial)
            c.fail("primary", "the primary basic DOF needs a material");
    }
    e.link2d = std::move(s);
    return e;
}

} // namespace hsmu
