#include "gui/cli/ConsoleStreams.h"

#include <QTextStream>

#include <cstdio>

namespace hsmu::gui {

QTextStream& ConsoleStreams::out() {
    static QTextStream stream(stdout);
    return stream;
}

QTextStream& ConsoleStreams::err() {
    static QTextStream stream(stderr);
    return stream;
}

} // namespace hsmu::gui
