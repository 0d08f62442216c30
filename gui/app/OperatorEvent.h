#pragma once
// OperatorEvent: one operator action on a test (pre-flight confirmation, start, pause, single
// step, resume, hold, stop, approve / reject an update, bounds, lock, fit-error threshold,
// updating policy, the choice for a specimen loaded by an earlier test), stamped by the test worker with the committed step, the test time [s] and
// the wall time (UTC), with the value before and after.
// The record keeps it language-neutral as an operator note (/notes, docs/recording.md):
//   "operator-event action=<key>; old=<value>; new=<value>; wall=<yyyy-MM-ddTHH:mm:ss.zzzZ>"
// (keys below; values in the law's normalized units, the policy by its configuration name);
// the console shows it translated in the alarm and event list (describe()).
// Thread rules: plain data, copied through queued signals.

#include <QCoreApplication>
#include <QMetaType>
#include <QString>

#include <optional>
#include <string>

namespace hsmu::gui {

struct OperatorEvent {
    Q_DECLARE_TR_FUNCTIONS(OperatorEvent)

public:
    // Action keys (language-neutral; the record's vocabulary).
    static constexpr const char* kPreflightConfirmed = "preflight-confirmed";
    /// Started without the pre-flight dialog (hsmu --start).
    static constexpr const char* kPreflightSkipped = "preflight-skipped";
    static constexpr const char* kStart = "start";
    static constexpr const char* kPause = "pause";
    static constexpr const char* kSingleStep = "single-step";
    static constexpr const char* kResume = "resume";
    static constexpr const char* kHold = "hold";
    static constexpr const char* kStop = "stop";
    static constexpr const char* kApprove = "approve-update";
    static constexpr const char* kReject = "reject-update";
    /// The twins' offsets (ModelUpdater::approveOffsets): old "#id element ...", new the
    /// offsets "u0=<v> <unit> F0=<v> <unit>".
    static constexpr const char* kApproveOffsets = "approve-offsets";
    static constexpr const char* kRejectOffsets = "reject-offsets";
    static constexpr const char* kBounds = "bounds";
    static constexpr const char* kLock = "lock";
    static constexpr const char* kThreshold = "fit-threshold";
    static constexpr const char* kPolicy = "updating-policy";
    /// The choice for a specimen loaded by an earlier test (pre-flight): old "<element>: <N>
    /// committed steps, last deformation <d> <unit>", new "continue", "fresh" (its controller
    /// reset it to step 0) or "fresh-refused" (the controller refused; nothing changed).
    static constexpr const char* kLoadedSpecimen = "loaded-specimen";
    /// An operator note (newValue: its text): shown in the event list; the record keeps the
    /// note itself in /notes, not as an operator-event row.
    static constexpr const char* kNote = "note";

    int step = 0;
    double time = 0.0;  ///< test time [s]
    QString wallTime;   ///< ISO 8601 UTC, milliseconds
    std::string action; ///< one of the keys above
    std::string oldValue;
    std::string newValue;

    /// Stamp an event with the current wall time.
    static OperatorEvent now(int step, double time, std::string action, std::string oldValue,
                             std::string newValue);
    /// The record's language-neutral text (format above).
    std::string recordText() const;
    /// The event a record's note holds (recordText()'s format; step and time are the note's
    /// own), or nothing for any other note.
    static std::optional<OperatorEvent> fromRecordText(const std::string& text);
    /// The operator's language, for the event list (e.g. "update #3 approved: ...").
    QString describe() const;
};

} // namespace hsmu::gui

Q_DECLARE_METATYPE(hsmu::gui::OperatorEvent)
