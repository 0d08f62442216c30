#include "gui/NumberOverrides.h"

namespace hsmu::gui {

void NumberOverrides::applyTo(TestConfig& cfg) const {
    if (recordDt)
        cfg.groundMotion.dt = *recordDt;
    if (scale)
        cfg.groundMotion.scale = *scale;
    if (dt)
        cfg.analysis.dt = *dt;
    if (duration)
        cfg.analysis.duration = *duration;
    if (allowUnstable)
        cfg.analysis.allowUnstable = true;
}

} // namespace hsmu::gui
