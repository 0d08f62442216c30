// hsmu-console: the console, the replay window and --plots (see gui/Launcher.h).
#include "gui/Launcher.h"

int main(int argc, char** argv) {
    return hsmu::gui::Launcher::main(argc, argv);
}
