#include "core/config/TestFactory.h"

#include "core/config/JsonCursor.h"
#include "core/config/NumericalSite.h"
#include "core/config/UpdatingConfig.h"
#include "core/updating/ModelUpdater.h"
#include "core/config/Link2dConfig.h"
#include "core/experimental/ExperimentalLink2d.h"
#include "core/experimental/ExperimentalElement.h"
#include "core/experimental/VirtualActuatorLab.h"
#include "core/groundmotion/GroundMotionReader.h"
#include "core/groundmotion/SyntheticGroundMotion.h"
#include "core/hysteresis/LawFactory.h"
#include "core/integration/AlphaOS.h"
#include "core/integration/ExplicitNewmark.h"
#include "core/structure/FlexibleColumnSpring.h"
#include "core/structure/Link2dElement.h"
#include "core/structure/SpringElement.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"

#include <cmath>
#include <filesystem>

namespace hsmu {

std::unique_ptr<HysteresisLaw> buildLaw(const MaterialSpec& m, const std::string& where)
{
    try {
        return makeLaw(m.law, m.params);
    } catch (const std::exception& e) {
        throw ConfigError(where + ": " + e.what());
    }
}

std::unique_ptr<ExperimentalControl> buildVirtualSpecimen(const ElementSpec& spec)
{
    if (spec.link2d) { // N actuators: each its uniaxial material, or the whole specimen
        const Link2dSpec& s = *spec.link2d;
        std::vector<VirtualActuator> lab;
        for (const ActuatorSpec& a : s.actuators) {
            const std::string where = "element '" + spec.name + "' actuator '" + a.channel.name + "'";
            lab.push_back({a.channel.name, a.channel.mode,
                           s.wholeSpecimen ? nullptr : buildLaw(a.material, where), a.model});
        }
        try {
            return std::make_unique<VirtualActuatorLab>(
                std::move(lab), s.wholeSpecimen ? buildWholeSpecimen(spec.name, s) : nullptr);
        } catch (const std::invalid_argument& x) {
            throw ConfigError("element '" + spec.name + "': " + x.what());
        }
    }
    auto law = buildLaw(spec.specimen.trueMaterial, "element '" + spec.name + "' specimen");
    return std::make_unique<VirtualSpecimen>(std::move(law), spec.specimen.options);
}

namespace {

// The law of a numerical element on a site (NumericalSite.h): its model law, computed elsewhere.
std::unique_ptr<HysteresisLaw> buildSiteLaw(const ElementSpec& e, std::unique_ptr<HysteresisLaw> model,
                                            const std::string& where)
{
    const NumericalSiteFactory factory = numericalSiteFactory();
    if (!factory)
        throw ConfigError(where + ": numericalSite " + e.numericalSite +
                          " is not supported here (the console and hsmu run support it; "
                          "elsewhere, e.g. hsmu compare, remove the field to run the element in "
                          "process)");
    try {
        auto law = factory(e, std::move(model));
        if (!law)
            throw ConfigError("no law was made");
        return law;
    } catch (const ConfigError& x) {
        throw ConfigError(where + ": numericalSite: " + x.what());
    } catch (const std::exception& x) {
        throw ConfigError(where + ": numericalSite: " + x.what());
    }
}

// A link2d element (Link2dConfig.h): numerical, or a specimen through its setup on the control
// the factory gives (in process: a VirtualActuatorLab of the actuators' materials).
std::unique_ptr<Element> buildLink2d(const ElementSpec& e, const ControlFactory& controls,
                                     const std::string& where)
{
    const Link2dSpec& s = *e.link2d;
    const Link2dGeometry g{s.dofs, s.length, s.angle, s.transformation};
    try {
        if (!e.experimental) {
            std::array<Link2dBasicDof, 3> dofs;
            for (int k = 0; k < 3; ++k) {
                if (s.basic[k].hasMaterial)
                    dofs[k].law = buildLaw(s.basic[k].material, where);
                dofs[k].heldForce = s.basic[k].heldForce;
                dofs[k].forceSchedule = s.basic[k].forceSchedule;
            }
            return std::make_unique<Link2dElement>(e.name, g, std::move(dofs), s.primary);
        }
        std::string error;
        auto setup = buildLink2dSetup(s, error);
        if (!setup)
            throw ConfigError(where + ": setup: " + error);
        std::vector<ActuatorChannelSpec> channels;
        for (const ActuatorSpec& a : s.actuators)
            channels.push_back(a.channel);
        auto control = controls ? controls(e) : buildVirtualSpecimen(e);
        if (!control)
            throw ConfigError(where + ": no experimental control could be made");
        auto x = std::make_unique<ExperimentalLink2d>(e.name, g, std::move(setup),
                                                      std::move(channels), std::move(control),
                                                      s.primary);
        x->setSite(e.site.empty() ? kDefaultSiteName : e.site);
        return x;
    } catch (const ConfigError&) {
        throw;
    } catch (const std::exception& x) {
        throw ConfigError(where + ": " + x.what());
    }
}

} // namespace

std::unique_ptr<Structure> buildStructure(const TestConfig& cfg, const ControlFactory& controls)
{
    auto s = std::make_unique<Structure>();
    for (const auto& d : cfg.dofs)
        s->addDof(d.name, d.mass, d.influence);
    for (const auto& [m, sl] : cfg.equalDofs)
        s->addEqualDof(m, sl);
    for (const auto& e : cfg.elements) {
        const std::string where = cfg.sourcePath + ": element '" + e.name + "'";
        if (e.link2d) {
            s->addElement(buildLink2d(e, controls, where));
            continue;
        }
        auto law = buildLaw(e.material, where);
        if (!e.numericalSite.empty())
            law = buildSiteLaw(e, std::move(law), where);
        if (e.experimental) {
            std::vector<DofTerm> terms{{e.dofs[0], 1.0}};
            if (e.type == "rotationalBaseSpring")
                terms[0].coefficient = 1.0 / e.height;
            else if (e.type == "truss") // a bearing or link between two DOFs
                terms = {{e.dofs[0], -1.0}, {e.dofs[1], 1.0}};
            auto control = controls ? controls(e) : buildVirtualSpecimen(e);
            if (!control)
                throw ConfigError(where + ": no experimental control could be made");
            auto x = std::make_unique<ExperimentalElement>(
                e.name, e.type, terms, std::move(control), e.limits, law->initialTangent());
            x->setSite(e.site.empty() ? kDefaultSiteName : e.site);
            s->addElement(std::move(x));
        } else if (e.type == "lateralSpring") {
            s->addElement(SpringElement::lateral(e.name, e.dofs[0], std::move(law)));
        } else if (e.type == "truss") {
            s->addElement(SpringElement::truss(e.name, e.dofs[0], e.dofs[1], std::move(law)));
        } else if (std::isfinite(e.ei)) {
            s->addElement(std::make_unique<FlexibleColumnSpring>(e.name, e.dofs[0], e.height,
                                                                 e.ei, std::move(law)));
        } else {
            s->addElement(SpringElement::rotationalRigid(e.name, e.dofs[0], e.height,
                                                         std::move(law)));
        }
    }
    switch (cfg.damping.kind) {
    case DampingSpec::Kind::None: break;
    case DampingSpec::Kind::ModalRatio:
        s->setModalDamping(cfg.damping.ratio, cfg.damping.modeI, cfg.damping.modeJ);
        break;
    case DampingSpec::Kind::Coefficients:
        s->setRayleigh({cfg.damping.a0, cfg.damping.a1});
        break;
    }
    return s;
}

std::unique_ptr<Integrator> buildIntegrator(const AnalysisSpec& a)
{
    if (a.integrator == "alphaOS")
        return std::make_unique<AlphaOS>(a.alpha);
    return std::make_unique<ExplicitNewmark>();
}

GroundMotion buildGroundMotion(const GroundMotionSpec& g, const std::string& configPath)
{
    GroundMotion gm;
    if (g.file.empty()) {
        gm = makeSyntheticGroundMotion(g.seed);
    } else {
        std::filesystem::path p(g.file);
        if (p.is_relative() && !configPath.empty())
            p = std::filesystem::path(configPath).parent_path() / p;
        GroundMotionFormat format = GroundMotionFormat::Auto;
        if (g.format == "at2")
            format = GroundMotionFormat::At2;
        else if (g.format == "time-acc")
            format = GroundMotionFormat::TimeAcceleration;
        else if (g.format == "single")
            format = GroundMotionFormat::SingleColumn;
        std::optional<AccelerationUnit> unit;
        if (!g.units.empty()) {
            unit = parseAccelerationUnit(g.units);
            if (!unit)
                throw ConfigError(configPath + ": groundMotion.units: expected g, m/s^2 or cm/s^2, "
                                               "found '" + g.units + "'");
        }
        std::optional<double> dt;
        if (g.dt > 0.0)
            dt = g.dt;
        gm = readGroundMotion(p, format, unit, dt);
    }
    if (g.scale != 1.0)
        gm = gm.scaled(g.scale);
    return gm;
}

std::unique_ptr<HybridTest> buildHybridTest(const TestConfig& cfg, const ControlFactory& controls)
{
    HybridTestOptions o;
    o.dt = cfg.analysis.dt;
    o.duration = cfg.analysis.duration;
    o.allowUnstable = cfg.analysis.allowUnstable;
    auto test = std::make_unique<HybridTest>(buildStructure(cfg, controls),
                                             buildIntegrator(cfg.analysis),
                                             buildGroundMotion(cfg.groundMotion, cfg.sourcePath), o);
    test->setUpdater(buildModelUpdater(cfg));
    return test;
}

} // namespace hsmu
