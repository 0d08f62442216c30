#include "core/session/ChannelComparison.h"

#include "core/session/ComparisonProtocol.h"

#include <cmath>
#include <limits>

namespace hsmu {

namespace {

/// `name` without `suffix` (" force" ...) if it ends with it, else "".
std::string stem(const std::string& name, const std::string& suffix)
{
    if (name.size() <= suffix.size() ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return {};
    return name.substr(0, name.size() - suffix.size());
}

int indexOf(const ChannelHistory& h, const std::string& element, const std::string& name)
{
    for (std::size_t i = 0; i < h.layout.size(); ++i)
        if (h.layout[i].element == element && h.layout[i].name == name)
            return static_cast<int>(i);
    return -1;
}

/// A channel's history from step 1: step 0 holds a specimen's initial state (all zero), not a
/// measurement (a numerical twin's held force is there already).
std::vector<double> measured(const ChannelHistory& h, const std::string& element,
                             const std::string& name)
{
    std::vector<double> x = channelSeries(h, element, name);
    if (!x.empty())
        x.erase(x.begin());
    return x;
}

/// compareSeries, with NRMSE NaN where the reference is zero to round-off beside the run
/// (RMS(x_ref) <= 1e-9 RMS(x)): a ratio to a round-off is no measure; the peak error is.
void compare(const std::vector<double>& x, const std::vector<double>& ref, double& nrmse,
             double& peak)
{
    compareSeries(x, ref, nrmse, peak);
    double sx = 0.0, sr = 0.0;
    for (std::size_t i = 0; i < x.size() && i < ref.size(); ++i) {
        sx += x[i] * x[i];
        sr += ref[i] * ref[i];
    }
    if (sx > 0.0 && std::sqrt(sr) <= 1e-9 * std::sqrt(sx))
        nrmse = std::numeric_limits<double>::quiet_NaN();
}

} // namespace

std::vector<double> channelSeries(const ChannelHistory& h, const std::string& element,
                                  const std::string& name)
{
    std::vector<double> out;
    const int i = indexOf(h, element, name);
    if (i < 0)
        return out;
    out.reserve(h.steps.size());
    for (const std::vector<double>& row : h.steps)
        out.push_back(static_cast<std::size_t>(i) < row.size() ? row[std::size_t(i)] : 0.0);
    return out;
}

std::vector<BasicDofComparison> compareBasicDofs(const ChannelHistory& run,
                                                 const ChannelHistory& reference)
{
    std::vector<BasicDofComparison> out;
    for (const ElementChannel& c : run.layout) {
        const std::string dof = stem(c.name, " deformation");
        if (dof.empty() || indexOf(run, c.element, dof + " force") < 0 ||
            indexOf(reference, c.element, c.name) < 0 ||
            indexOf(reference, c.element, dof + " force") < 0)
            continue;
        BasicDofComparison b;
        b.element = c.element;
        b.dof = dof;
        b.deformationUnit = c.unit;
        b.forceUnit = run.layout[std::size_t(indexOf(run, c.element, dof + " force"))].unit;
        compare(measured(run, c.element, c.name),
                      measured(reference, c.element, c.name), b.deformationNrmse,
                      b.deformationPeakError);
        compare(measured(run, c.element, dof + " force"),
                      measured(reference, c.element, dof + " force"), b.forceNrmse,
                      b.forcePeakError);
        out.push_back(std::move(b));
    }
    return out;
}

std::vector<ActuatorComparison> compareActuators(const ChannelHistory& run,
                                                 const ChannelHistory* reference, double dt)
{
    std::vector<ActuatorComparison> out;
    for (const ElementChannel& c : run.layout) {
        const std::string actuator = stem(c.name, " command");
        const int force = indexOf(run, c.element, actuator + " force");
        if (actuator.empty() || force < 0 || indexOf(run, c.element, actuator + " stroke") < 0)
            continue;
        ActuatorComparison a;
        a.element = c.element;
        a.actuator = actuator;
        a.commandUnit = c.unit;
        a.forceUnit = run.layout[std::size_t(force)].unit;
        // A command in the force's unit is a held force (force control).
        a.control = c.unit == a.forceUnit ? "force" : "displacement";
        a.tracking = rths::trackingReport(
            measured(run, c.element, c.name),
            measured(run, c.element, actuator + (a.control == "force" ? " force" : " stroke")),
            dt);
        if (reference && indexOf(*reference, c.element, actuator + " force") >= 0) {
            a.compared = true;
            compare(measured(run, c.element, actuator + " force"),
                          measured(*reference, c.element, actuator + " force"),
                          a.forceNrmse, a.forcePeakError);
        }
        out.push_back(std::move(a));
    }
    return out;
}

} // namespace hsmu
