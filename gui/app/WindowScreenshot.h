#pragma once
// WindowScreenshot: `--screenshot FILE --screenshot-after SECONDS` of the console and of the
// replay window: after the delay the window is grabbed into FILE (PNG), the outcome is
// printed on stderr ("PREFIX: screenshot FILE" or "PREFIX: FILE: cannot be written") and the
// event loop quits with 0 (written) or 1. Works offscreen.
// Thread rules: GUI thread, with a QApplication.

#include <QString>

class QWidget;

namespace hsmu::gui {

class WindowScreenshot {
public:
    /// window must outlive the event loop run that follows.
    static void schedule(QWidget& window, const QString& file, double seconds,
                         const QString& prefix);
};

} // namespace hsmu::gui
