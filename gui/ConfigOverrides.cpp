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
    NumberOverrides::applyTo(cfg);
}

} // namespace hsmu::gui
