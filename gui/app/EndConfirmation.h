#pragma once
// EndConfirmation: the non-blocking "end the test and keep the data?" question asked before
// Stop or Quit ends a running test. The default button continues the test (Enter never ends
// one); the emergency hold's action stays alive over the window-modal box.
// Object names (tests): the box as given, buttons "confirmEnd" and "continueTest".
// Thread rules: GUI thread only.

#include <functional>

class QAction;
class QMessageBox;
class QString;
class QWidget;

namespace hsmu::gui {

struct EndConfirmation {
    /// Open the box over `parent` (deleted on close); done(true) runs when the operator chose
    /// `yes`, done(false) otherwise.
    static QMessageBox* open(QWidget* parent, const QString& objectName, const QString& question,
                             const QString& yes, QAction* emergencyHold,
                             std::function<void(bool confirmed)> done);
};

} // namespace hsmu::gui
