// hsmu: the headless subcommands in this process, everything drawn by hsmu-console
// (see gui/cli/CliLauncher.h).
#include "gui/cli/CliLauncher.h"

int main(int argc, char** argv) {
    return hsmu::gui::CliLauncher::main(argc, argv);
}
