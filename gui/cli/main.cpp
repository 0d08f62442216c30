// hsmu: a plain `hsmu run FILE` in this process without Qt, every other command line handed
// to hsmu-cli (Qt Core), which hands the console to hsmu-console (see gui/cli/FastRun.h).
#include "gui/cli/FastRun.h"

int main(int argc, char** argv) {
    return hsmu::gui::FastRun::main(argc, argv);
}
