#include "core/session/ComparisonProtocol.h"

#include "core/config/JsonCursor.h"
#include "core/config/TestFactory.h"
#include "core/structure/Structure.h"
#include "core/experiment/HybridTest.h"
#include "core/output/RunStatistics.h"
#include "core/session/TestSession.h"
#include "core/structure/Link2dKinematics.h"
#include "core/updating/ModelUpdater.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>

namespace hsmu {

namespace {

ElementSpec* findElement(TestConfig& cfg, const std::string& name)
{
    for (auto& e : cfg.elements)
        if (e.name == name)
            return &e;
    return nullptr;
}

std::string comparedElement(const TestConfig& cfg, const ComparisonOptions& o)
{
    if (!o.element.empty())
        return o.element;
    if (!cfg.updating.enabled || cfg.updating.targets.empty())
        throw ConfigError(cfg.sourcePath + ": compare: the configuration has no updating target "
                                           "(give the compared element explicitly)");
    return cfg.updating.targets.front().element;
}

/// Records the compared element and DOF, and the updater's estimates.
class Collector final : public StepObserver {
public:
    Collector(ComparisonRun& run, int element, int dof) : m_run(run), m_e(element), m_d(dof) {}
    void onStep(const StepRecord& r) override
    {
        m_run.time.push_back(r.time);
        m_run.deformation.push_back(r.elements[m_e].deformation);
        m_run.force.push_back(r.elements[m_e].force);
        m_run.displacement.push_back(r.u[m_d]);
        if (!r.channels.empty())
            m_run.channels.steps.push_back(r.channels);
        if (r.hasUpdating) {
            m_run.parameters.push_back(r.updating.parameters);
            m_run.stddev.push_back(r.updating.stddev);
            m_run.appliedUpdates = r.updating.appliedUpdates;
        }
    }

private:
    ComparisonRun& m_run;
    int m_e, m_d;
};

ComparisonRun runOne(int index, const std::string& name, const TestConfig& cfg,
                     const std::string& element, const std::string& dof,
                     const std::function<void(double)>& progress, const std::string& recordDir)
{
    ComparisonRun run;
    run.name = name;
    auto test = buildHybridTest(cfg);
    const auto& elements = test->structure().elements();
    int e = -1;
    for (std::size_t i = 0; i < elements.size(); ++i)
        if (elements[i]->name() == element)
            e = static_cast<int>(i);
    const auto& dofs = test->structure().dofNames();
    const int d = static_cast<int>(std::find(dofs.begin(), dofs.end(), dof) - dofs.begin());
    if (e < 0 || d >= static_cast<int>(dofs.size()))
        throw ConfigError(cfg.sourcePath + ": compare: no element '" + element + "' or DOF '" +
                          dof + "'");
    const RunLayout layout = RunLayout::of(test->structure());
    run.sites = layout.sites;
    run.linkSecurity = builtinSiteSecurity(layout);
    run.channels.layout = layout.channels;
    SessionOptions options; // as fast as possible, no automatic resume
    if (!recordDir.empty()) {
        options.recordPath = recordDir + "/" + name + "/record.h5";
        options.recordStart = RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt, name};
        options.recordStart.siteSecurity = run.linkSecurity;
    }
    (void)index;
    RunStatistics stats(layout);
    TestSession session(std::move(test), options);
    const HybridTest& t = session.test();
    Collector collector(run, e, d);
    session.addObserver(&collector);
    session.addObserver(&stats);
    if (!session.openRecord())
        throw ConfigError(session.lastError());
    if (!session.prepare())
        throw ConfigError(cfg.sourcePath + ": compare (" + name + "): " + session.lastError());
    if (t.updater())
        run.parameterNames = t.updater()->parameterNames();
    const int total = std::max(1, t.totalSteps());
    int reported = 0;
    session.runToEnd([&](const TestSession::Progress&) {
        if (progress && t.currentStep() / 500 > reported) {
            reported = t.currentStep() / 500;
            progress(double(t.currentStep()) / total);
        }
    });
    session.removeObserver(&collector);
    session.removeObserver(&stats);
    for (std::size_t i = 0; i < layout.elements.size(); ++i)
        if (const rths::TrackingReport* tracked = stats.tracking(i, t.dt())) {
            run.tracking.emplace_back(layout.elements[i].name, *tracked);
            run.trackingUnits.push_back(layout.elements[i].units.deformation);
        }
    if (!session.finish())
        run.recordError = session.lastError();
    run.steps = t.currentStep();
    run.finalState = testStateName(t.state());
    for (const auto& a : t.alarms()) {
        std::ostringstream s;
        s << "t = " << a.time << " s: " << a.message;
        run.alarms.push_back(s.str());
    }
    return run;
}

ComparisonMetric metric(const ComparisonRun& run, const ComparisonRun& ref)
{
    ComparisonMetric m;
    compareSeries(run.force, ref.force, m.forceNrmse, m.forcePeakError);
    compareSeries(run.displacement, ref.displacement, m.displacementNrmse,
                  m.displacementPeakError);
    return m;
}

} // namespace

void compareSeries(const std::vector<double>& x, const std::vector<double>& ref, double& nrmse,
                   double& peak)
{
    const std::size_t n = std::min(x.size(), ref.size());
    double se = 0.0, sr = 0.0;
    peak = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double d = x[i] - ref[i];
        se += d * d;
        sr += ref[i] * ref[i];
        peak = std::max(peak, std::abs(d));
    }
    nrmse = sr > 0.0 ? std::sqrt(se / sr) : (se > 0.0 ? INFINITY : 0.0);
}

TestConfig referenceConfig(const TestConfig& cfg, const ComparisonOptions& o)
{
    TestConfig ref = cfg;
    const std::string name = comparedElement(cfg, o);
    const ElementSpec* specimen = findElement(ref, cfg.updating.specimen);
    if (!specimen || !specimen->experimental)
        throw ConfigError(cfg.sourcePath + ": compare: the updating specimen '" +
                          cfg.updating.specimen + "' is not an experimental element");
    const ElementSpec truth = *specimen;
    // Every element the updating reaches, and the compared one, becomes a copy of the true
    // specimen: the "exact" structure the updated run tries to approach.
    std::vector<std::string> replaced{name};
    for (const auto& t : cfg.updating.targets)
        if (t.element != name)
            replaced.push_back(t.element);
    for (std::size_t i = 0; i < replaced.size(); ++i) {
        ElementSpec* target = findElement(ref, replaced[i]);
        if (!target || target->experimental)
            throw ConfigError(cfg.sourcePath + ": compare: '" + replaced[i] +
                              "' is not a numerical element");
        if (target->type != truth.type || std::isfinite(target->ei))
            throw ConfigError(cfg.sourcePath + ": compare: '" + replaced[i] +
                              "' must have the specimen's element type (and a rigid column) to "
                              "be replaced by a copy of the true specimen");
        target->experimental = true;
        if (truth.link2d && target->link2d) { // the specimen's setup, actuators and lab
            target->link2d->basic = truth.link2d->basic;
            target->link2d->setupScript = truth.link2d->setupScript;
            target->link2d->actuators = truth.link2d->actuators;
            target->link2d->wholeSpecimen = truth.link2d->wholeSpecimen;
        }
        target->specimen = truth.specimen;
        target->specimen.options.forceNoiseStd = 0.0;
        target->specimen.options.deformationNoiseStd = 0.0;
        target->specimen.options.seed = truth.specimen.options.seed + 1 + i;
        target->limits = truth.limits;
    }
    ref.updating.enabled = false;
    return ref;
}

TestConfig initialConfig(const TestConfig& cfg)
{
    TestConfig c = cfg;
    c.updating.enabled = false;
    return c;
}

ComparisonResult runComparison(const TestConfig& cfg, const ComparisonOptions& o,
                               const std::function<void(int, double)>& progress)
{
    if (!cfg.updating.enabled)
        throw ConfigError(cfg.sourcePath + ": compare needs an enabled \"updating\" section");
    ComparisonResult r;
    r.element = comparedElement(cfg, o);
    TestConfig c = cfg;
    const ElementSpec* e = findElement(c, r.element);
    if (!e)
        throw ConfigError(cfg.sourcePath + ": compare: no element '" + r.element + "'");
    r.dof = o.dof.empty() ? cfg.dofs.at(e->dofs.back()).name : o.dof;
    if (o.dof.empty() && e->link2d) // a link2d: node j's first free DOF (its top's sway)
        for (int k = 3; k < 6; ++k)
            if (const int d = e->link2d->dofs[std::size_t(k)]; d >= 0) {
                r.dof = cfg.dofs.at(std::size_t(d)).name;
                break;
            }
    const bool rotational = e->type == "rotationalBaseSpring";
    r.forceUnit = rotational ? "kN m" : "kN";
    r.deformationUnit = rotational ? "rad" : "m";
    if (e->link2d) { // its reported (primary) basic DOF
        r.forceUnit = link2dBasicForceUnit(e->link2d->primary);
        r.deformationUnit = link2dBasicDeformationUnit(e->link2d->primary);
    }
    auto p = [&](int i) {
        return [&, i](double f) {
            if (progress)
                progress(i, f);
        };
    };
    r.reference = runOne(0, "reference", referenceConfig(cfg, o), r.element, r.dof, p(0), o.recordDir);
    r.initial = runOne(1, "initial", initialConfig(cfg), r.element, r.dof, p(1), o.recordDir);
    r.updated = runOne(2, "updated", cfg, r.element, r.dof, p(2), o.recordDir);
    r.initialMetric = metric(r.initial, r.reference);
    r.updatedMetric = metric(r.updated, r.reference);
    const double dt = cfg.analysis.dt;
    r.reference.actuators = compareActuators(r.reference.channels, nullptr, dt);
    for (ComparisonRun* run : {&r.initial, &r.updated}) {
        run->basicDofs = compareBasicDofs(run->channels, r.reference.channels);
        run->actuators = compareActuators(run->channels, &r.reference.channels, dt);
    }
    return r;
}

} // namespace hsmu
