#pragma once
// MaterialCommand: `hsmu material --law boucWen|bilinear|elastic --param NAME=VALUE ...
// --history FILE [--out FILE]`: drive one hysteresis law through a deformation history
// (core/hysteresis/MaterialDriver.h) and write "deformation,force,tangent" CSV to --out or
// stdout. Units are the law's own. Exit codes: 0 done, 1 an error (message on stderr).
// Thread rules: main thread; needs only a QCoreApplication.

#include <QCoreApplication>
#include <QStringList>

namespace hsmu::gui {

class MaterialCommand {
    Q_DECLARE_TR_FUNCTIONS(MaterialCommand)
public:
    /// arguments: the process arguments (program, "material", ...). Returns the exit code.
    static int exec(const QStringList& arguments);
};

} // namespace hsmu::gui
