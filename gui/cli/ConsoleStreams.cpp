#include "gui/cli/ConsoleStreams.h"

#include <QCommandLineParser>
#include <QStringList>
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

std::optional<QString> ConsoleStreams::parse(QCommandLineParser& parser,
                                             const QStringList& arguments) {
    if (!parser.parse(arguments))
        return parser.errorText();
    if (parser.isSet(QStringLiteral("help"))) {
        out() << parser.helpText() << Qt::flush;
        return QString();
    }
    return std::nullopt;
}

} // namespace hsmu::gui
