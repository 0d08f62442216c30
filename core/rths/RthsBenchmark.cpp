#include "core/rths/RthsBenchmark.h"

#include <algorithm>
#include <cmath>

namespace hsmu::rths {

RthsSettings benchmarkSampleController()
{
    RthsSettings s;
    s.pid = PidGains{2.0, 95.0, 0.0, 0.0};
    s.compensation.type = CompensationSettings::Type::None;
    s.compensation.lead.enabled = true;
    return s;
}

RthsSettings defaultCompensation(const PlantParameters& nominal)
{
    RthsSettings s = benchmarkSampleController();
    s.plant = nominal;
    s.compensation.type = CompensationSettings::Type::Ats;
    s.compensation.fitToLoop = true;
    fitFeedforward([&](double w) { return closedLoopResponse(s, w); }, 0.2, 6.0, s.compensation);
    return s;
}

void fitToNominalLoop(RthsSettings& s)
{
    if (s.compensation.fitToLoop)
        fitFeedforward([&](double w) { return closedLoopResponse(s, w); }, 0.2, 6.0, s.compensation);
}

Partition benchmarkPartition(int benchmarkCase, const PlantParameters& plant)
{
    return partition(benchmarkReference(benchmarkCase), Specimen{0, plant.me, plant.ce, plant.ke});
}

std::complex<double> closedLoopResponse(const RthsSettings& s, double omega)
{
    using C = std::complex<double>;
    const double h = 1.0 / s.rate;
    const C sz(0.0, 2.0 / h * std::tan(0.5 * omega * h)); // Tustin's s at z = e^{j w h}
    C c = s.pid.kp + s.pid.ki / sz;
    if (s.pid.kd != 0.0)
        c += s.pid.kd * sz / (s.pid.tauD * sz + 1.0);
    const C lead = s.compensation.lead.enabled
                       ? s.compensation.lead.gain * (sz + s.compensation.lead.zero) /
                             (sz + s.compensation.lead.pole)
                       : C(1.0);
    const C gd = s.plant.frequencyResponse(omega) * std::exp(C(0.0, -0.5 * omega * h));
    return lead * c * gd / (1.0 + c * gd);
}

double loopDelay(const RthsSettings& s, double f)
{
    const double w = 2.0 * M_PI * f;
    return -std::arg(closedLoopResponse(s, w)) / w;
}

RthsRun runRths(const Partition& partition, const GroundMotion& groundMotion,
                const RthsSettings& settings, TickGate* gate, double duration,
                TickObserver* observer, TwinUpdateSource* updates)
{
    RthsLoop loop(partition, groundMotion, settings);
    const double h = loop.period();
    const double length = duration > 0.0 ? std::min(duration, groundMotion.duration())
                                         : groundMotion.duration();
    const long n = long(std::floor(length / h + 1e-9)) + 1;
    RthsRun run;
    std::string gateHold;
    const auto floors = partition.reference.m.rows();
    for (auto* v : {&run.time, &run.desired, &run.command, &run.measured, &run.force})
        v->reserve(std::size_t(n));
    std::vector<Eigen::VectorXd> hybrid;
    hybrid.reserve(std::size_t(n));
    // The reference before the loop (cheap: RK4 of the linear structure), so that each tick
    // can be recorded with it as it happens.
    const Eigen::MatrixXd reference = referenceResponse(partition.reference, groundMotion, h, n);
    for (long k = 0; k < n; ++k) {
        if (gate && !gate->admit(k, gateHold))
            break;
        for (TwinUpdate u; updates && updates->next(k, u);) {
            run.updates.push_back(loop.updateTwin(u));
            if (observer)
                observer->onUpdate(k, run.updates.back());
        }
        const bool advanced = loop.tick();
        if (gate)
            gate->done(k);
        const RthsTick& t = loop.last(); // sampled even when the tick held
        run.time.push_back(t.time);
        run.desired.push_back(t.desired);
        run.command.push_back(t.command);
        run.measured.push_back(t.measured);
        run.force.push_back(t.force);
        hybrid.push_back(t.floors);
        if (observer)
            observer->onTick(k, t, reference.row(k));
        if (updates && advanced)
            updates->observe(k, t.measured, t.damperForce);
        run.peakForce = std::max(run.peakForce, std::abs(loop.plant().force()));
        run.peakStroke = std::max(run.peakStroke, std::abs(loop.plant().displacement()));
        run.peakVelocity = std::max(run.peakVelocity, std::abs(loop.plant().velocity()));
        if (!advanced)
            break;
    }
    run.hold = loop.holdReason().empty() ? gateHold : loop.holdReason();
    if (loop.twin())
        run.twin = loop.twin()->law().parameters();
    const long m = long(run.time.size());
    run.hybrid.resize(m, floors);
    for (long k = 0; k < m; ++k)
        run.hybrid.row(k) = hybrid[std::size_t(k)].transpose();
    run.reference = reference.topRows(m);
    if (m < 2)
        return run;
    const auto col = [](const Eigen::MatrixXd& a, int i) {
        return std::vector<double>(a.col(i).data(), a.col(i).data() + a.rows());
    };
    const int j = partition.specimen.dof;
    auto& c = run.criteria.j;
    const TrackingReport tracking = trackingReport(run.desired, run.measured, h);
    c[0] = tracking.j1;
    c[1] = tracking.j2;
    c[2] = tracking.j3;
    c[3] = normalizedRmsError(col(run.reference, j), run.measured);
    c[4] = peakError(col(run.reference, j), run.measured);
    // J6..J9: the two numerical floors after the specimen's (the benchmark's floors 2 and 3).
    int slot = 0;
    for (int i = 0; i < int(floors) && slot < 2; ++i) {
        if (i == j)
            continue;
        c[5 + slot] = normalizedRmsError(col(run.reference, i), col(run.hybrid, i));
        c[7 + slot] = peakError(col(run.reference, i), col(run.hybrid, i));
        ++slot;
    }
    run.frequency = tracking.frequency;
    run.trackingIndicator = tracking.indicator;
    return run;
}

PlantParameters perturbedPlant(const PlantParameters& nominal, PortableRandom& random)
{
    PlantParameters p = nominal;
    const double zetaE = nominal.ce / (2.0 * std::sqrt(nominal.ke * nominal.me));
    do
        p.a3 = nominal.a3 + 1.3 * random.normal();
    while (p.a3 <= 0.0);
    p.b1 = nominal.b1 + 3.3 * random.normal();
    p.b2 = nominal.b2 + 3.3e3 * random.normal();
    p.ke = nominal.ke + 5e4 * random.normal();
    p.ce = PlantParameters::specimenDamping(zetaE, p.ke, p.me);
    return p;
}

} // namespace hsmu::rths
