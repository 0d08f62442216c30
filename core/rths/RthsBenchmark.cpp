#include "core/rths/RthsBenchmark.h"
#include "core/rths/RthsRunner.h"

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
    RthsRunner runner(partition, groundMotion, settings, gate, duration, observer, updates);
    runner.run();
    return runner.result();
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
