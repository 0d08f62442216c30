#include "gui/app/WindowScreenshot.h"

#include "gui/cli/ConsoleStreams.h"

#include <QCoreApplication>
#include <QPixmap>
#include <QTextStream>
#include <QTimer>
#include <QWidget>

namespace hsmu::gui {

void WindowScreenshot::schedule(QWidget& window, const QString& file, double seconds,
                                const QString& prefix) {
    QWidget* w = &window;
    QTimer::singleShot(int(seconds * 1000.0), w, [w, file, prefix] {
        const bool saved = w->grab().save(file, "PNG");
        if (saved)
            ConsoleStreams::err() << prefix << ": screenshot " << file << Qt::endl;
        else
            ConsoleStreams::err() << prefix << ": " << file << ": cannot be written" << Qt::endl;
        QCoreApplication::exit(saved ? 0 : 1);
    });
}

} // namespace hsmu::gui
