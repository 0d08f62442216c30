#include "core/config/UpdatingConfig.h"

#include "core/config/ConfigLoader.h"
#include "core/config/TestFactory.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/hysteresis/MrDamper.h"
#include "core/record/RecordReader.h"
#include "core/record/SpecimenColumns.h"
#include "core/structure/Link2dKinematics.h"
#include "core/updating/ModelUpdater.h"
#include "core/updating/MrDamperUkfIdentifier.h"
#include "core/updating/NelderMeadIdentifier.h"
#include "core/updating/PinchingUkfIdentifier.h"
#include "core/updating/RobustUkfIdentifier.h"
#include "core/updating/UkfIdentifier.h"

#include <filesystem>

namespace hsmu {

namespace {

const ElementSpec* findElement(const TestConfig& cfg, const std::string& name)
{
    for (const auto& e : cfg.elements)
        if (e.name == name)
            return &e;
    return nullptr;
}

std::vector<std::string> stringList(const JsonCursor& c, const std::string& key)
{
    std::vector<std::string> out;
    const JsonCursor a = c.child(key);
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!a.node()[i].is_string())
            a.fail("", "expected an array of parameter names");
        out.push_back(a.node()[i].get<std::string>());
    }
    return out;
}

/// The paper updates all but A0 and deltaA.
std::vector<std::string> defaultTargetParameters(const std::string& law)
{
    if (law == "boucWen")
        return {"k0", "alpha", "n", "beta", "gamma", "deltaNu", "deltaEta"};
    if (law == "boucWenPinching")
        return {"k0",    "alpha", "n", "beta", "gamma", "deltaNu",  "deltaEta",
                "zetaS", "p",     "q", "psi",  "deltaPsi", "lambda"};
    if (law == "bilinear")
        return {"k0", "fy", "b"};
    if (law == "mrDamper") // all but A (with alpha, it only sets the scale of z) and the scales
        return {"c0", "c1", "k0", "k1", "f0", "alpha", "beta", "gamma", "n"};
    return {"k"};
}

/// A basic DOF as configured ("basicDof": an index or a link2d DOF's name) of an element of
/// `count` basic DOFs of type `type`; fails naming the field when it is out of range.
int parseBasicDof(const JsonCursor& c, int count, const std::string& type)
{
    const auto& v = c.node().at("basicDof");
    int k = -1;
    if (v.is_string()) {
        k = count == 3 ? link2dBasicDofIndex(v.get<std::string>()) : -1;
        if (k < 0)
            c.fail("basicDof", count == 3 ? "expected 0 .. 2 or axial, shear, rotation, found '" +
                                                v.get<std::string>() + "'"
                                          : "a " + type + " has one basic DOF (0), found '" +
                                                v.get<std::string>() + "'");
    } else if (v.is_number_integer()) {
        k = v.get<int>();
    } else {
        c.fail("basicDof", "expected a basic DOF index or name");
    }
    if (k < 0 || k >= count)
        c.fail("basicDof", "basic DOF " + std::to_string(k) + " is out of range: a " + type +
                               " has " + std::to_string(count) + " (0 .. " +
                               std::to_string(count - 1) + ")");
    return k;
}

/// Seeds the robust UKF with the specimen's measured response in a previous run's record
/// (rows 1 .. N-1: row 0 is the state at rest). Throws ConfigError naming the file and field.
/// basicDof >= 0: that basic DOF's channels (SpecimenColumns.h), else the specimen's columns.
void seedFromRecord(RobustUkfIdentifier& id, const std::string& path, const std::string& specimen,
                    int basicDof, const std::string& where)
{
    const std::string field = where + ": ukf.seedRecord '" + path + "': ";
    std::vector<double> u, f;
    try {
        const RecordReader reader(path);
        const RecordData& r = reader.data();
        const SpecimenColumns c = specimenColumns(
            r, specimen, "", basicDof >= 0 ? link2dBasicDofName(basicDof) : "");
        for (int row = 1; row < r.rows(); ++row) {
            u.push_back(c.deformation(r, row));
            f.push_back(c.force(r, row));
        }
    } catch (const std::exception& e) {
        throw ConfigError(field + e.what());
    }
    std::string message;
    if (!id.seed(u, f, message))
        throw ConfigError(field + message);
}

} // namespace

UpdatingSpec parseUpdating(const JsonCursor& c, const TestConfig& cfg)
{
    c.allowOnly({"enabled", "specimen", "basicDof", "model", "method", "bounds", "ukf",
                 "nelderMead", "inspector", "reporter", "approval", "maxConsecutiveRejections",
                 "offsets"});
    UpdatingSpec u;
    u.enabled = c.boolean("enabled", true);
    u.specimen = c.string("specimen");
    const ElementSpec* sp = findElement(cfg, u.specimen);
    if (!sp || !sp->experimental)
        c.fail("specimen", "expected the name of an experimental element, found '" + u.specimen + "'");
    // The identified basic DOF and its initial model (docs/configuration.md, updating).
    if (sp->link2d) {
        u.basicDof = c.has("basicDof") ? parseBasicDof(c, 3, "link2d") : sp->link2d->primary;
        if (!c.has("model"))
            c.fail("model", "a link2d specimen's basic DOFs carry no material (their forces come "
                            "from its actuators): give the identified basic DOF's (" +
                                std::string(link2dBasicDofName(u.basicDof)) +
                                ") initial model, e.g. { \"law\": \"boucWen\", ... }");
        u.model = parseMaterial(c.child("model"));
    } else {
        if (c.has("basicDof"))
            parseBasicDof(c, 1, sp->type); // 0 or refused: the one DOF is today's path (-1)
        if (c.has("model"))
            c.fail("model", "only for a link2d specimen: '" + u.specimen +
                                "' is identified from its own material");
        u.model = sp->material;
    }
    const MaterialSpec& model = u.model;
    u.method = c.string("method", "ukf");
    if (u.method != "ukf" && u.method != "nelderMead")
        c.fail("method", "expected 'ukf' or 'nelderMead'");
    if (u.method == "ukf" && model.law != "boucWen" &&
        model.law != "boucWenPinching" && model.law != "mrDamper")
        c.fail("method", "the UKF identifies a boucWen model, a boucWenPinching model or an "
                         "mrDamper model; the specimen's model is '" + model.law +
                             "' (use nelderMead)");
    if (auto it = model.params.find("uRef"); it != model.params.end())
        u.modelURef = it->second;
    if (auto it = model.params.find("fRef"); it != model.params.end())
        u.modelFRef = it->second;
    if (c.has("bounds")) {
        const JsonCursor b = c.child("bounds");
        b.requireObject();
        for (auto it = b.node().begin(); it != b.node().end(); ++it) {
            const auto& v = it.value();
            if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number() ||
                v[0].get<double>() > v[1].get<double>())
                b.fail(it.key(), "expected [lower, upper] with lower <= upper");
            u.bounds[it.key()] = {v[0].get<double>(), v[1].get<double>()};
        }
    }
    if (c.has("ukf")) {
        const JsonCursor k = c.child("ukf");
        k.allowOnly({"formulation", "a", "b", "kappa", "forceNoise", "parameterNoise",
                     "initialStdFraction", "seedRecord"});
        u.ukfFormulation = k.string("formulation", u.ukfFormulation);
        if (u.ukfFormulation != "robust" && u.ukfFormulation != "paper")
            k.fail("formulation", "expected 'robust' or 'paper'");
        u.seedRecord = k.string("seedRecord", "");
        if (!u.seedRecord.empty()) {
            if (u.ukfFormulation != "robust")
                k.fail("seedRecord", "only the robust formulation is seeded");
            std::filesystem::path p(u.seedRecord);
            if (p.is_relative() && !cfg.sourcePath.empty())
                u.seedRecord = (std::filesystem::path(cfg.sourcePath).parent_path() / p).string();
        }
        u.ukfA = k.number("a", u.ukfA);
        u.ukfB = k.number("b", u.ukfB);
        if (k.has("kappa"))
            u.ukfKappa = k.number("kappa");
        u.forceNoise = k.number("forceNoise", u.forceNoise);
        u.parameterNoise = k.number("parameterNoise", u.parameterNoise);
        u.initialStdFraction = k.number("initialStdFraction", u.initialStdFraction);
        if (!(u.ukfA > 0.0))
            k.fail("a", "expected a > 0");
        if (!(u.forceNoise > 0.0))
            k.fail("forceNoise", "expected a noise std > 0 (fraction of fRef)");
        if (u.parameterNoise < 0.0 || u.initialStdFraction < 0.0)
            k.fail("", "expected non-negative noise fractions");
    }
    if (c.has("nelderMead")) {
        const JsonCursor n = c.child("nelderMead");
        n.allowOnly({"maxEvaluations", "cooldown", "window", "parameters", "refit"});
        u.nelderMeadRefit = n.string("refit", u.nelderMeadRefit);
        if (u.nelderMeadRefit != "auto" && u.nelderMeadRefit != "calibration" &&
            u.nelderMeadRefit != "simplex")
            n.fail("refit", "expected 'auto', 'calibration' or 'simplex'");
        u.maxEvaluations = n.integer("maxEvaluations", u.maxEvaluations);
        u.cooldown = n.number("cooldown", u.cooldown);
        u.fitWindow = n.number("window", u.fitWindow);
        if (n.has("parameters"))
            u.parameters = stringList(n, "parameters");
        if (u.maxEvaluations < 1)
            n.fail("maxEvaluations", "expected at least 1");
    }
    if (u.method == "nelderMead" && u.parameters.empty())
        u.parameters = defaultTargetParameters(model.law);
    // No fracture is judged before the specimen carried a tenth of its reference force.
    {
        const auto& mp = model.params;
        const std::string& law = model.law;
        const char* key = law == "boucWen" || law == "boucWenPinching" || law == "mrDamper"
                              ? "fRef"
                              : (law == "bilinear" ? "fy" : "");
        if (*key)
            u.inspector.minimumForce = 0.1 * (mp.count(key) ? mp.at(key) : 1.0);
    }
    if (c.has("inspector")) {
        const JsonCursor i = c.child("inspector");
        i.allowOnly({"window", "threshold", "fractureDrop", "minimumForce", "pinnedTime",
                     "trackingWindow", "trackingJ2Limit", "trackingInterval"});
        auto& s = u.inspector;
        s.window = i.number("window", s.window);
        s.threshold = i.number("threshold", s.threshold);
        s.fractureDrop = i.number("fractureDrop", s.fractureDrop);
        s.minimumForce = i.number("minimumForce", s.minimumForce);
        s.pinnedTime = i.number("pinnedTime", s.pinnedTime);
        s.trackingWindow = i.number("trackingWindow", s.trackingWindow);
        s.trackingJ2Limit = i.number("trackingJ2Limit", s.trackingJ2Limit);
        s.trackingInterval = i.number("trackingInterval", s.trackingInterval);
        if (!(s.window > 0.0) || !(s.trackingWindow > 0.0) || !(s.trackingInterval > 0.0))
            i.fail("", "expected positive windows and interval [s]");
    }
    if (c.has("reporter")) {
        const JsonCursor r = c.child("reporter");
        r.allowOnly({"policy", "everyN", "proposalInterval", "targets"});
        const std::string policy = r.string("policy", "everyStep");
        auto p = parseReporterPolicy(policy);
        if (!p)
            r.fail("policy", "expected everyStep, zeroCrossing, everyNSteps or onApproval");
        u.policy = *p;
        u.everyN = r.integer("everyN", u.everyN);
        if (u.everyN < 1)
            r.fail("everyN", "expected at least 1");
        u.proposalInterval = r.number("proposalInterval", u.proposalInterval);
        if (!(u.proposalInterval >= 0.0))
            r.fail("proposalInterval", "expected a time [s] of at least 0");
        if (r.has("targets")) {
            const JsonCursor ts = r.child("targets");
            for (std::size_t k = 0; k < ts.size(); ++k) {
                const JsonCursor t = ts.at(k);
                t.allowOnly({"element", "basicDof", "parameters", "scale"});
                ReporterTarget target;
                target.element = t.string("element");
                const ElementSpec* te = findElement(cfg, target.element);
                if (!te || te->experimental)
                    t.fail("element", "expected a numerical element, found '" + target.element + "'");
                // A link2d twin: its basic DOF matching the specimen's (or its own basicDof).
                const MaterialSpec* law = &te->material;
                if (te->link2d) {
                    target.basicDof = t.has("basicDof") ? parseBasicDof(t, 3, "link2d")
                                      : u.basicDof >= 0 ? u.basicDof
                                                        : te->link2d->primary;
                    const Link2dBasicSpec& b = te->link2d->basic[std::size_t(target.basicDof)];
                    if (!b.hasMaterial)
                        t.fail(t.has("basicDof") ? "basicDof" : "element",
                               "basic DOF " + std::to_string(target.basicDof) + " (" +
                                   link2dBasicDofName(target.basicDof) + ") of '" +
                                   target.element + "' carries no hysteretic law (" +
                                   (b.heldForce != 0.0 ? "a held force" : "a free DOF") +
                                   "): nothing to update");
                    law = &b.material;
                } else if (t.has("basicDof")) {
                    parseBasicDof(t, 1, te->type);
                }
                if (law->law != model.law)
                    t.fail("element", "its law '" + law->law +
                                          "' differs from the specimen model's '" +
                                          model.law + "'");
                target.parameters = t.has("parameters") ? stringList(t, "parameters")
                                                        : defaultTargetParameters(law->law);
                if (t.has("scale")) {
                    const JsonCursor s = t.child("scale");
                    s.requireObject();
                    for (auto it = s.node().begin(); it != s.node().end(); ++it)
                        target.scale[it.key()] = s.number(it.key());
                }
                u.targets.push_back(std::move(target));
            }
        }
    }
    u.approval = c.string("approval", u.approval);
    if (u.approval != "manual" && u.approval != "approveAll" && u.approval != "rejectAll")
        c.fail("approval", "expected manual, approveAll or rejectAll");
    u.maxConsecutiveRejections = c.integer("maxConsecutiveRejections", u.maxConsecutiveRejections);
    u.offsets = c.string("offsets", u.offsets);
    if (!calibrationOffsetsFromName(u.offsets))
        c.fail("offsets", "expected off, auto or on");
    return u;
}

std::unique_ptr<Identifier> buildIdentifier(const UpdatingSpec& u, const HysteresisLaw& model,
                                            double dt, const std::string& where)
{
    try {
        if (model.parameterIndex("forceOffset") >= 0 ||
            model.parameterIndex("deformationOffset") >= 0)
            throw ConfigError(where + ": the specimen model has offsets (deformationOffset, "
                                      "forceOffset); the online identifiers fit none: calibrate "
                                      "them offline (hsmu replay --offsets) or online "
                                      "(updating.offsets), the operator approving them for the "
                                      "twins");
        if (u.method == "ukf" && model.lawName() == "boucWenPinching") {
            if (u.ukfFormulation != "robust")
                throw ConfigError(where + ": the paper's UKF formulation identifies a boucWen "
                                          "model; boucWenPinching takes the robust one (the "
                                          "default)");
            return std::make_unique<PinchingUkfIdentifier>(
                static_cast<const BoucWenPinching&>(model).parameters(), u.modelURef,
                u.modelFRef, u.bounds);
        }
        if (u.method == "ukf" && model.lawName() == "mrDamper") {
            if (u.ukfFormulation != "robust")
                throw ConfigError(where + ": the paper's UKF formulation identifies a boucWen "
                                          "model; mrDamper takes the robust one (the default)");
            const auto* mr = dynamic_cast<const MrDamper*>(&model);
            if (!mr)
                throw ConfigError(where + ": the MR damper UKF needs an mrDamper specimen model");
            return std::make_unique<MrDamperUkfIdentifier>(*mr, u.modelURef, u.modelFRef,
                                                           u.bounds);
        }
        if (u.method == "ukf") {
            const auto* bw = dynamic_cast<const BoucWen*>(&model);
            if (!bw)
                throw ConfigError(where + ": the UKF needs a boucWen specimen model");
            if (u.ukfFormulation == "robust") {
                auto id = std::make_unique<RobustUkfIdentifier>(bw->parameters(), u.modelURef,
                                                                u.modelFRef, u.bounds);
                if (!u.seedRecord.empty())
                    seedFromRecord(*id, u.seedRecord, u.specimen, u.basicDof, where);
                return id;
            }
            BoucWenUkfSettings s;
            s.ukf.a = u.ukfA;
            s.ukf.b = u.ukfB;
            s.ukf.kappa = u.ukfKappa;
            s.forceNoise = u.forceNoise;
            s.parameterNoise = u.parameterNoise;
            s.initialStdFraction = u.initialStdFraction;
            return std::make_unique<UkfIdentifier>(bw->parameters(), s, u.bounds);
        }
        NelderMeadIdentifierSettings s;
        s.parameters = u.parameters;
        s.bounds = u.bounds;
        s.uRef = u.modelURef;
        s.fRef = u.modelFRef;
        s.maxEvaluations = u.maxEvaluations;
        s.cooldownSteps = static_cast<int>(u.cooldown / dt + 0.5);
        s.windowSteps = static_cast<int>(u.fitWindow / dt + 0.5);
        s.calibrated = u.nelderMeadRefit == "calibration" ||
                       (u.nelderMeadRefit == "auto" && (model.lawName() == "boucWen" ||
                                                        model.lawName() == "boucWenPinching" ||
                                                        model.lawName() == "mrDamper"));
        return std::make_unique<NelderMeadIdentifier>(model, s);
    } catch (const std::invalid_argument& e) {
        throw ConfigError(where + ": " + e.what());
    }
}

std::unique_ptr<ModelUpdater> buildModelUpdater(const TestConfig& cfg)
{
    const UpdatingSpec& u = cfg.updating;
    if (!u.enabled)
        return nullptr;
    const ElementSpec* sp = findElement(cfg, u.specimen);
    const std::string where = cfg.sourcePath + ": updating";
    if (!sp)
        throw ConfigError(where + ": no element '" + u.specimen + "'");
    auto aux = buildLaw(u.model, where);
    aux->setTimeIncrement(cfg.analysis.dt); // a rate-dependent model: the identifier's too
    std::unique_ptr<Identifier> identifier = buildIdentifier(u, *aux, cfg.analysis.dt, where);
    auto reporter = std::make_unique<Reporter>(u.targets, u.policy, u.everyN);
    reporter->setProposalInterval(u.proposalInterval);
    auto updater = std::make_unique<ModelUpdater>(u.specimen, std::move(aux), std::move(identifier),
                                                  u.inspector, std::move(reporter));
    updater->setBasicDof(u.basicDof);
    if (u.approval == "approveAll")
        updater->setAutoResolve(true);
    else if (u.approval == "rejectAll")
        updater->setAutoResolve(false);
    updater->setMaxConsecutiveRejections(u.maxConsecutiveRejections);
    if (const auto offsets = calibrationOffsetsFromName(u.offsets);
        offsets && *offsets != CalibrationOffsets::Off)
        updater->setOffsetCheck(
            std::make_unique<OffsetCheck>(updater->auxiliaryModel().lawName(), *offsets));
    return updater;
}

} // namespace hsmu
