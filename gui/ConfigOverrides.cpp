#include "gui/ConfigOverrides.h"

#include <QFileInfo>

namespace hsmu::gui {

void ConfigOverrides::applyTo(TestConfig& cfg) const {
    if (!groundMotionFile.isEmpty()) {
        cfg.groundMotion.file = QFileInfo(groundMotionFile).absoluteFilePath().toStdString();
        cfg.groundMotion.format = "auto";
        cfg.groundMotion.units.clear();
        cfg.groundMotion.dt = 0.0;
    }
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
