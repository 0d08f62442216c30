#include "gui/app/RunState.h"

#include <QCoreApplication>

namespace hsmu::gui {

QString describe(RunState state) {
    switch (state) {
    case RunState::Idle:
        return QCoreApplication::translate("RunState", "no test loaded");
    case RunState::Ready:
        return QCoreApplication::translate("RunState", "ready");
    case RunState::Running:
        return QCoreApplication::translate("RunState", "running");
    case RunState::Paused:
        return QCoreApplication::translate("RunState", "paused");
    case RunState::Holding:
        return QCoreApplication::translate("RunState", "holding");
    case RunState::Finished:
        return QCoreApplication::translate("RunState", "finished");
    case RunState::Stopped:
        return QCoreApplication::translate("RunState", "stopped");
    case RunState::Failed:
        return QCoreApplication::translate("RunState", "failed");
    }
    return {};
}

} // namespace hsmu::gui
