#pragma once
// GroundMotionCheck: the console's own check of a file chosen as a ground motion, before the
// reader: a binary file (an image, a PDF, an HDF5 record ...) is named as such at once,
// instead of the reader's guess at a format. Thread rules: any thread.

#include <QCoreApplication>
#include <QString>

namespace hsmu::gui {

class GroundMotionCheck {
    Q_DECLARE_TR_FUNCTIONS(GroundMotionCheck)

public:
    /// "" if the file's first 4 KiB look like text (or it cannot be opened: the reader
    /// names a missing file itself); else a translated sentence naming the file.
    static QString binaryFileProblem(const QString& path);
};

} // namespace hsmu::gui
