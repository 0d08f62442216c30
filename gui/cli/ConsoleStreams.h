#pragma once
// ConsoleStreams: the process's stdout and stderr as QTextStreams (UTF-8, numbers formatted
// by QString, i.e. with a '.' decimal point whatever the locale).
// Thread rules: main thread only.

class QTextStream;

namespace hsmu::gui {

class ConsoleStreams {
public:
    static QTextStream& out();
    static QTextStream& err();
};

} // namespace hsmu::gui
