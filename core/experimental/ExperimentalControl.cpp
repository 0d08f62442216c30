#include "core/experimental/ExperimentalControl.h"

namespace hsmu {

ControlResult ExperimentalControl::setTargets(const Eigen::VectorXd& commands)
{
    if (commands.size() != 1)
        return ControlResult::fault(description() + ": one actuator channel, " +
                                    std::to_string(commands.size()) + " commands");
    return setTarget(commands[0]);
}

ControlResult ExperimentalControl::measureChannels(Eigen::VectorXd& strokes, Eigen::VectorXd& forces)
{
    ControlMeasurement m;
    ControlResult r = measure(m);
    if (!r.ok)
        return r;
    strokes.resize(1);
    forces.resize(1);
    strokes[0] = m.deformation;
    forces[0] = m.force;
    return r;
}

} // namespace hsmu
