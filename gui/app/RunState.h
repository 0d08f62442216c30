#pragma once
// RunState: the console's view of a test, as the controller reports it to the widgets.
// (HybridTest::State is core's; Paused and Stopped exist only in the console: a pause stops
// stepping between steps with the specimen where it is, a stop ends the test in a safe hold.)
// Thread rules: plain enum, passed through queued signals.

#include <QMetaType>
#include <QString>

namespace hsmu::gui {

enum class RunState {
    Idle,     ///< nothing loaded
    Ready,    ///< loaded, not started
    Running,  ///< stepping
    Paused,   ///< between steps, by the operator
    Holding,  ///< safe hold: emergency hold, limit or fault (resume retries the step)
    Finished, ///< ran to the end of the record / duration
    Stopped,  ///< ended by the operator
    Failed    ///< could not start (e.g. unstable); the message says why
};

/// Translated word for a state, e.g. "running".
QString describe(RunState state);

} // namespace hsmu::gui

Q_DECLARE_METATYPE(hsmu::gui::RunState)
