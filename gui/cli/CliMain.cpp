// hsmu-cli: the headless subcommands in this process (Qt Core), everything drawn by
// hsmu-console (see gui/cli/CliLauncher.h); started by hsmu (gui/cli/FastRun.h).
#include "gui/cli/CliLauncher.h"

int main(int argc, char** argv) {
    return hsmu::gui::CliLauncher::main(argc, argv);
}
