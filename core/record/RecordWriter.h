#pragma once
// RecordWriter: a StepObserver writing the HDF5 record of a run (schema: docs/recording.md).
//
//   /                       attributes schema_version, program, program_version, start_time,
//                           configuration (JSON text), config_name, operator_notes, dt [s]
//   /steps/{step,time,ground_acceleration}            [N]
//   /dofs/{u,v,a}                                     [N x nDof]   attribute names, units
//   /elements/{deformation,force,commanded}           [N x nElem]  attributes names, units, ...
//   /elements/actuator/{commanded,measured,held_ticks,flags}  [N x nElem]  the actuator
//            channels of each specimen's control (NaN where it reports none)
//   /updating/{parameters,stddev} [N x nParam], {auxiliary_force,fit_error,applied_updates,
//            updates_this_step,pending_proposals,update_requested} [N], tracking [N x 3]
//            (the inspector's J1 [s], J2, J3), events/{step,time,element (an /elements
//            column index)} [E],
//            events/values [E x nParam]      (only with online model updating)
//   /alarms/{time,step,severity,kind,message}         [M]
//   /notes/{time,step,text}                           [K] operator notes added mid-run
//
// The file is created with the latest format and switched to SWMR write mode, so another
// process can read it (RecordReader, h5py with swmr=True) while the run goes on. Rows are
// buffered in memory and appended (extend + write + H5Fflush) at least every kFlushInterval
// seconds of wall time (on CoarseClock), whenever the rows received reach a multiple of
// batchRowsFor() (whole chunks, also after a flush by time cut a batch short;
// kMaxBufferedRows at most), and by flush() / finish() / the destructor: a process killed
// mid-run leaves a file holding every step flushed before.
// Off the stepping thread (issue 27): onStep() only copies the row into a batch whose
// capacity was reserved up front (no allocation per row); a flush hands the batch to the
// writer's own thread (RecordThread), which writes it while the next batch fills. A flush
// waits while the previous batch is still being written (back-pressure: no row is ever
// dropped; at most two batches, 2 x kMaxBufferedRows rows, are not yet on disk). flush() and
// finish() return once the rows are on disk; rowsFlushed(), alarmsFlushed() and
// notesFlushed() count what the writer's thread has written so far.
// onStep() only checks the clock when rows are buffered; a test that holds (no steps) should
// have its owner call flushIfDue() at least once a second while it holds (TestSession::tick(),
// core/session, does for every front end) so that held rows, alarms and notes reach the file.
// Alarms: trackAlarms(&test.alarms()) makes every onStep()/flush() append the alarms raised
// since the last call; or call writeAlarms() yourself.
// Errors: the constructor throws RecordError naming the file; a later write failure stops
// recording (ok() false, error() says why) and never throws out of onStep().
//
// Thread rules: every call on one thread (the test's). After the constructor, HDF5 is used
// by the writer's thread only (one batch at a time), then by finish() once that thread has
// been joined; core uses HDF5 from no other thread.

#include "core/output/RunLayout.h"
#include "core/output/DofRecording.h"
#include "core/record/RecordSchema.h"
#include "core/util/Alarm.h"
#include "core/experiment/StepRecord.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace hsmu {

struct RecordStart {
    std::string configuration; ///< JSON text (TestConfig::raw.dump())
    std::string configName;    ///< TestConfig::name
    std::string operatorNotes;
    double dt = 0.0; ///< integration step [s]
    /// Which run of a protocol this is ("reference", "initial", "updated" for hsmu compare;
    /// "" for a single run). The configuration is the one given to the command.
    std::string run{};
    /// Deflate level 1-9 (with HDF5's shuffle filter) of the per-step DOF, element and
    /// actuator matrices; 0 (the default) writes them uncompressed (docs/recording.md).
    int deflate = 0;
    /// How each site's link is protected (RunLayout.h SiteSecurity), written as /sites'
    /// attribute `security` in the order of RunLayout::sites (securityOfSites,
    /// docs/recording.md); empty: not written.
    SiteSecurity siteSecurity{};
    /// The numerical DOFs /dofs/u, v, a keep and the stride of their rows (issue 27,
    /// docs/recording.md "Chosen and decimated DOFs"); full() (the default): every DOF at
    /// every step, the record unchanged. Otherwise /dofs gets the attributes `dof_indices`
    /// and `every` and the datasets /dofs/step and /dofs/time of the rows kept. Nothing else
    /// is ever decimated. Indices must be ascending, unique and < the layout's DOFs.
    DofRecording dofRecording{};
};

class RecordWriter final : public StepObserver {
public:
    static constexpr double kFlushInterval = 0.5; ///< [s] of wall time
    static constexpr int kMaxBufferedRows = recordschema::kChunkRows; // crash safety: <= 1,000 rows behind steps.csv
    /// Also flush once the buffered per-step values (DOF and element columns) reach this
    /// many doubles (8 MiB): a 10,000-DOF model flushes every 18 rows, bounding memory (two
    /// batches, one filling and one being written, hold what one batch of 16 MiB did).
    static constexpr long kMaxBufferedValues = 1L << 20;
    /// Rows of one batch (a flush when the batch is full) for a layout of nDof DOFs and nElem
    /// elements: at most kMaxBufferedRows and kMaxBufferedValues / (3 (nDof + nElem)) rows,
    /// rounded down to a whole number of the widest per-step matrix's chunks
    /// (recordschema::chunkRowsFor), so that each chunk is written once: 500 for small models,
    /// 10 at 10,000 DOFs (issue 27).
    static int batchRowsFor(std::size_t nDof, std::size_t nElem);

    /// Creates (truncates) path. Throws RecordError naming the file on failure.
    RecordWriter(const std::string& path, const RunLayout& layout, const RecordStart& start);
    ~RecordWriter() override;
    RecordWriter(const RecordWriter&) = delete;
    RecordWriter& operator=(const RecordWriter&) = delete;

    void onStep(const StepRecord& record) override;
    /// Append alarms[k..] where k is the number already written (a growing vector).
    void writeAlarms(const std::vector<Alarm>& alarms);
    /// Not owned; must outlive every later onStep()/flush()/finish(); nullptr to stop.
    void trackAlarms(const std::vector<Alarm>* alarms);
    /// An operator note at test time `time` [s] and step `step`, written with the next flush
    /// (cut at recordschema::kNoteChars bytes). Ignored once the writer failed or finished.
    void addNote(double time, int step, const std::string& text);
    /// Flush if rows, alarms or notes are buffered and kFlushInterval elapsed since the last flush.
    void flushIfDue();
    /// Write every buffered row and alarm, then H5Fflush. False if recording failed.
    bool flush();
    /// Flush and close the file. False if any write failed. Idempotent.
    bool finish();
    /// Append one operator note to the /notes of the finished (closed) record at `path`: the
    /// run has ended, the console still shows it and the operator adds a remark. False with
    /// *error (naming the file) when it cannot be written.
    static bool appendNote(const std::string& path, double time, int step,
                           const std::string& text, std::string* error);

    bool ok() const;
    const std::string& error() const;
    const std::string& path() const;
    int rowsReceived() const; ///< onStep() calls so far
    int rowsFlushed() const;  ///< rows on disk (after the last successful flush)
    int alarmsFlushed() const;
    int notesFlushed() const; ///< notes written to the file (counted when appended)

private:
    struct Impl;
    std::unique_ptr<Impl> m_d;
};

} // namespace hsmu
