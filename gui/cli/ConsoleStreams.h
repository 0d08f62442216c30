#pragma once
// ConsoleStreams: the process's stdout and stderr as QTextStreams (UTF-8, numbers formatted
// by QString, i.e. with a '.' decimal point whatever the locale), and the subcommands' shared
// handling of parse errors and --help.
// Thread rules: main thread only.

#include <QString>
#include <QStringList>

#include <optional>

class QCommandLineParser;
class QTextStream;

namespace hsmu::gui {

class ConsoleStreams {
public:
    static QTextStream& out();
    static QTextStream& err();
    /// Parse a subcommand's arguments: nullopt to go on, an empty string after printing
    /// --help on out(), else the parser's error text.
    static std::optional<QString> parse(QCommandLineParser& parser, const QStringList& arguments);
};

} // namespace hsmu::gui
