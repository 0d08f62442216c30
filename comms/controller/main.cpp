// hsmu-controller: the virtual actuator controller as a server process (ControllerApp).
#include "comms/controller/ControllerApp.h"

#include <cstdio>

int main(int argc, char** argv) {
    using hsmu::comms::ControllerCommandLine;
    std::string error;
    const auto cmd = ControllerCommandLine::parse(argc, argv, error);
    if (!cmd) {
        std::fprintf(stderr, "hsmu-controller: %s\n%s", error.c_str(),
                     ControllerCommandLine::usage());
        return 2;
    }
    if (cmd->help) {
        std::fputs(ControllerCommandLine::usage(), stdout);
        return 0;
    }
    hsmu::comms::ControllerApp app(*cmd);
    if (!app.start(error)) {
        std::fprintf(stderr, "hsmu-controller: %s\n", error.c_str());
        return app.usageRefused() ? 2 : 1;
    }
    return app.run();
}
