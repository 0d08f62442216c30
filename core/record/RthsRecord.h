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
    /// The resume of a held run, as a note at tick k (docs/rths.md, "Hold and resume").
    void onResume(long k, double t, const std::string& note) override;

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
/// the file closed; held() between a hold and a resume. The console's RTHS view and
/// hsmu-controller --rths --record record through it (docs/rths.md); twin updates and resumes
/// are notes at their tick.
class RthsRecording {
public:
    /// Throws (RecordError, std::runtime_error) when the folder or the file cannot be created.
    RthsRecording(const std::string& dir, const RecordStart& start, const GroundMotion& groundMotion,
                  int floors);
    const std::string& path() const { return m_path; }
    TickObserver* feed() { return &m_feed; }
    /// The run held and may resume (RthsRunner): its rthsHoldAlarm at its last tick, flushed;
    /// the file stays open for the ticks after a resume. False with error() when not written.
    bool held(const RthsRun& run, bool deadlineMiss);
    /// false with error() when the file could not be completed (every flushed tick stays). A
    /// held run's alarm is written here unless held() wrote it for the same hold.
    bool finish(const RthsRun& run, bool deadlineMiss);
    const std::string& error() const { return m_writer.error(); }

private:
    std::string m_path;
    RecordWriter m_writer;
    RthsRecordFeed m_feed;
    std::string m_holdWritten; // the hold whose alarm held() wrote
    std::vector<Alarm> m_holds; // every hold's alarm so far
};

} // namespace hsmu::rths
