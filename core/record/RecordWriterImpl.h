#pragma once
// RecordWriter::Impl: the writer's state, shared by RecordWriter.cpp (buffering, the record
// thread, flushing) and RecordWriterCreate.cpp (the file and its datasets as
// docs/recording.md lays them out). Private to core/record (HDF5 inside).

#include "core/record/RecordWriter.h"

#include "core/Version.h"
#include "core/hysteresis/BoucWen.h"
#include "core/record/ActuatorColumns.h"
#include "core/record/Hdf5Util.h"
#include "core/record/RecordChecksum.h"
#include "core/record/RecordData.h"
#include "core/record/RecordError.h"
#include "core/record/RecordSchema.h"
#include "core/record/RecordThread.h"
#include "core/util/CoarseClock.h"
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace hsmu {

struct RecordWriter::Impl {
    std::string path;
    RunLayout layout;
    std::size_t nDof = 0, nElem = 0, nPar = 0, nSite = 0, nChan = 0;
    // The DOFs chosen or decimated (RecordStart::dofRecording not full): nKept columns of
    // /dofs/u, v, a (nDof otherwise), rows of the steps that are multiples of `every`.
    bool dofsChosen = false;
    std::vector<int> keptDofs; // indices into the layout's DOFs (every DOF when !dofsChosen)
    int every = 1;
    std::size_t nKept = 0;
    h5::Id file;
    h5::Id severityType, kindType, messageType, noteType;
    h5::Extendible step, time, ag, u, v, a, def, force, cmd;
    h5::Extendible dofStep, dofTime; // /dofs/step, /dofs/time (dofsChosen only)
    h5::Extendible par, sd, aux, fit, applied, thisStep, pending, tracking, requested;
    h5::Extendible eventStep, eventTime, eventElement, eventValues, eventDecision, eventProposal;
    h5::Extendible alarmTime, alarmStep, alarmSeverity, alarmKind, alarmMessage, alarmCode;
    h5::Extendible noteTime, noteStep, noteText;
    h5::Extendible siteRoundTrip;
    h5::Extendible channels; // /elements/channels (multi-DOF elements)
    ActuatorColumns actuator; // /elements/actuator

    /// Rows, alarms and notes buffered between two flushes.
    struct Batch {
        std::vector<int> bStep, bDofStep, bApplied, bThisStep, bPending, bRequested, bEventStep,
            bEventElement, bEventDecision, bEventProposal;
        std::vector<double> bTime, bDofTime, bAg, bU, bV, bA, bDef, bForce, bCmd, bPar, bSd, bAux,
            bFit, bTracking, bEventTime, bEventValues, bSiteRoundTrip, bChannels;
        ActuatorColumns::Rows actuator;
        std::vector<Alarm> bAlarms;
        std::vector<RecordNote> bNotes;

        void clear();
        /// Capacity for `rows` rows, so that appending a row never allocates.
        void reserve(std::size_t rows, std::size_t nDof, std::size_t nElem, std::size_t nPar,
                     std::size_t nSite, std::size_t nChan);
    };
    // `fill` belongs to the stepping thread; `out` to the record thread while it writes it
    // (between RecordThread::start() and the next wait()), to the stepping thread otherwise.
    Batch fill, out;
    std::unique_ptr<RecordThread> thread;

    const std::vector<Alarm>* tracked = nullptr;
    std::size_t alarmsSeen = 0;
    int received = 0;
    int batchRows = 1; // rows per batch (batchRowsFor)
    std::atomic<int> flushed{0}, alarmsFlushed{0}, notesFlushed{0}; // by the record thread
    std::atomic<bool> failed{false}; // set by the record thread once `error` is written
    bool closed = false;
    std::string error;
    CoarseClock::time_point lastFlush = CoarseClock::now(); // read once a row: coarse

    void create(const RecordStart& start);
    void createUpdating(hid_t root);
    void createLogs(hid_t root);
    void writeBuffers(const Batch& b);
    void writeLogs(const Batch& b);
    void writeOut(); // the record thread's job: writes and clears `out`
    bool hasBuffered() const;
    void bufferEvent(const UpdateEvent& ev);
    void bufferChosenDofs(const StepRecord& r); // a kept row of the chosen DOFs
    /// Hands the buffered rows to the record thread; with `synchronous`, waits until they
    /// are on disk.
    bool flush(bool synchronous);
    std::vector<h5::Extendible*> datasets();
};

} // namespace hsmu
