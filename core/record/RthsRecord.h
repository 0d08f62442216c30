#pragma once
// RthsRecord: an RTHS run as a run record (docs/rths.md, "Outputs"; schema docs/recording.md),
// so that `hsmu export`, the console's replay and `hsmu.Record` read it like any test. Each
// loop tick is one row (step k = tick k, time k h [s]):
//   /dofs/u        the hybrid floors 1..n ("floor i") [m], then the reference structure's
//                  floors ("reference floor i") [m]; /dofs/v and /dofs/a are NaN (the loop
//                  keeps no per-floor velocity or acceleration in its outputs)
//   /elements      one experimental element "specimen" (type "servoHydraulic", m and N):
//                  deformation = measured xm, force = measured fm, commanded = desired y;
//                  /elements/actuator: commanded = x* after compensation, measured = xm
//   /steps/ground_acceleration  the record at t [m/s^2]
// Ticks reach the record through RecordWriter (batched, on its own thread) as they happen.

#include "core/experiment/StepRecord.h"
#include "core/groundmotion/GroundMotion.h"
#include "core/output/RunLayout.h"
#include "core/record/RecordWriter.h"
#include "core/rths/RthsBenchmark.h"
#include "core/record/RecordWriter.h"
#include "core/util/Alarm.h"

namespace hsmu::rths {

/// The critical alarm a held run leaves in its record's /alarms at its last tick (docs/rths.md,
/// "The benchmark"): ControlFault for the deadline-miss policy (deadlineMiss), OperatorHold
/// for a console's hold or emergency hold, LimitExceeded for a limit of the plant or command;
/// the message is run.hold. Only for a held run (run.hold not empty).
Alarm rthsHoldAlarm(const RthsRun& run, bool deadlineMiss);

/// The record's layout for a partition with `floors` floors.
RunLayout rthsLayout(int floors);

/// Turns ticks into StepRecords for a StepObserver (a RecordWriter). No allocation per tick.
class RthsRecordFeed final : public TickObserver {
public:
    /// notes: where the twin updates go, as notes at their tick (describeTwinUpdate); nullptr:
    /// nowhere.
    RthsRecordFeed(StepObserver& sink, const GroundMotion& groundMotion, int floors,
                   RecordWriter* notes = nullptr);
    void onTick(long k, const RthsTick& tick,
                const Eigen::Ref<const Eigen::RowVectorXd, 0, Eigen::InnerStride<>>& reference) override;
    void onUpdate(long k, const UpdateEvent& event) override;

private:
    StepObserver& m_sink;
    RecordWriter* m_notes;
    const GroundMotion& m_ag;
    int m_floors;
    StepRecord m_row;
};

/// The first free DIR/record.h5, DIR/record-2.h5, DIR/record-3.h5, ... (DIR created when
/// missing): an earlier run's record is never overwritten. Throws std::runtime_error naming
/// the folder when it cannot be created.
std::string firstFreeRecordPath(const std::string& dir);

/// One RTHS run's record in folder DIR, at firstFreeRecordPath(DIR): the RecordWriter (batched
/// on its own thread) and the RthsRecordFeed the loop hands its ticks to (feed(), from the
/// loop's thread); finish() after the loop: a held run's rthsHoldAlarm at its last tick, then
/// the file closed. The console's RTHS view records through it (docs/rths.md).
class RthsRecording {
public:
    /// Throws (RecordError, std::runtime_error) when the folder or the file cannot be created.
    RthsRecording(const std::string& dir, const RecordStart& start, const GroundMotion& groundMotion,
                  int floors);
    const std::string& path() const { return m_path; }
    TickObserver* feed() { return &m_feed; }
    /// false with error() when the file could not be completed (every flushed tick stays).
    bool finish(const RthsRun& run, bool deadlineMiss);
    const std::string& error() const { return m_writer.error(); }

private:
    std::string m_path;
    RecordWriter m_writer;
    RthsRecordFeed m_feed;
};

} // namespace hsmu::rths
