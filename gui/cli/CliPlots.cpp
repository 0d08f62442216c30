#include "gui/cli/CliPlots.h"

namespace hsmu::gui {

CliPlots& CliPlots::installed() {
    static CliPlots plots;
    return plots;
}

} // namespace hsmu::gui
