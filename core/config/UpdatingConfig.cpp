#include "core/config/UpdatingConfig.h"

#include "core/config/TestFactory.h"
#include "core/hysteresis/BoucWen.h"
#include "core/hysteresis/BoucWenPinching.h"
#include "core/hysteresis/MrDamper.h"
#include "core/record/RecordReader.h"
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

/// Seeds the robust UKF with the specimen's measured response in a previous run's record
/// (rows 1 .. N-1: row 0 is the state at rest). Throws ConfigError naming the file and field.
void seedFromRecord(RobustUkfIdentifier& id, const std::string& path, const std::string& specimen,
                    const std::string& where)
{
    const std::string field = where + ": ukf.seedRecord '" + path + "': ";
    std::vector<double> u, f;
    try {
        const RecordReader reader(path);
        const RecordData& r = reader.data();
        int j = -1;
        for (std::size_t i = 0; i < r.layout.elements.size(); ++i)
            if (r.layout.elements[i].name == specimen && r.layout.elements[i].experimental)
                j = int(i);
        if (j < 0)
            throw ConfigError(field + "no specimen (experimental element) named '" + specimen +
                              "' in the record");
        for (int row = 1; row < r.rows(); ++row) {
            u.push_back(r.deformation(row, j));
            f.push_back(r.force(row, j));
        }
    } catch (const ConfigError&) {
        throw;
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
    c.allowOnly({"enabled", "specimen", "method", "bounds", "ukf", "nelderMead", "inspector",
                 "reporter", "approval", "maxConsecutiveRejections", "offsets"});
    UpdatingSpec u;
    u.enabled = c.boolean("enabled", true);
    u.specimen = c.string("specimen");
    const ElementSpec* sp = findElement(cfg, u.specimen);
    if (!sp || !sp->experimental)
        c.fail("specimen", "expected the name of an experimental element, found '" + u.specimen + "'");
    u.method = c.string("method", "ukf");
    if (u.method != "ukf" && u.method != "nelderMead")
        c.fail("method", "expected 'ukf' or 'nelderMead'");
    if (u.method == "ukf" && sp->material.law != "boucWen" &&
        sp->material.law != "boucWenPinching" && sp->material.law != "mrDamper")
        c.fail("method", "the UKF identifies a boucWen model, a boucWenPinching model or an "
                         "mrDamper model; the specimen's model is '" + sp->material.law +
                             "' (use nelderMead)");
    if (auto it = sp->material.params.find("uRef"); it != sp->material.params.end())
        u.modelURef = it->second;
    if (auto it = sp->material.params.find("fRef"); it != sp->material.params.end())
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
        u.parameters = defaultTargetParameters(sp->material.law);
    // No fracture is judged before the specimen carried a tenth of its reference force.
    {
        const auto& mp = sp->material.params;
        const std::string& law = sp->material.law;
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
                t.allowOnly({"element", "parameters", "scale"});
                ReporterTarget target;
                target.element = t.string("element");
                const ElementSpec* te = findElement(cfg, target.element);
                if (!te || te->experimental)
                    t.fail("element", "expected a numerical element, found '" + target.element + "'");
                if (te->material.law != sp->material.law)
                    t.fail("element", "its law '" + te->material.law +
                                          "' differs from the specimen model's '" +
                                          sp->material.law + "'");
                target.parameters = t.has("parameters") ? stringList(t, "parameters")
                                                        : defaultTargetParameters(te->material.law);
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
                    seedFromRecord(*id, u.seedRecord, u.specimen, where);
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
    auto aux = buildLaw(sp->material, where);
    aux->setTimeIncrement(cfg.analysis.dt); // a rate-dependent model: the identifier's too
    std::unique_ptr<Identifier> identifier = buildIdentifier(u, *aux, cfg.analysis.dt, where);
    auto reporter = std::make_unique<Reporter>(u.targets, u.policy, u.everyN);
    reporter->setProposalInterval(u.proposalInterval);
    auto updater = std::make_unique<ModelUpdater>(u.specimen, std::move(aux), std::move(identifier),
                                                  u.inspector, std::move(reporter));
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
