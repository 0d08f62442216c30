#include "gui/app/GroundMotionCheck.h"

#include <QFile>
#include <QFileInfo>

namespace hsmu::gui {

QString GroundMotionCheck::binaryFileProblem(const QString& path) {
    QFile f(path);
    if (path.isEmpty() || !f.open(QIODevice::ReadOnly))
        return {};
    const QByteArray head = f.read(4096);
    int control = 0;
    for (const char c : head)
        if (c == '\0' || (uchar(c) < 0x20 && c != '\n' && c != '\r' && c != '\t'))
            ++control;
    if (control == 0)
        return {};
    return tr("%1 is not a text file of numbers (it holds binary data, e.g. an image); "
              "expected a PEER AT2 record, two columns (time, acceleration) or one column of "
              "values")
        .arg(QFileInfo(path).fileName());
}

} // namespace hsmu::gui
