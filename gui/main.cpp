// hsmu: the console and its headless subcommands (see gui/Launcher.h).
#include "gui/Launcher.h"

int main(int argc, char** argv) {
    return hsmu::gui::Launcher::main(argc, argv);
}
