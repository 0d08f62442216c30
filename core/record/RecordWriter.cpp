#include "core/record/RecordWriter.h"

#include "core/record/RecordWriterImpl.h"

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

namespace hsmu {

namespace {

using Clock = CoarseClock; // the flush interval is checked once a row
const double kNaN = std::nan("");

/// Copies text into a fixed field of `chars` bytes, cut at a UTF-8 character boundary.
void putFixed(std::vector<char>& out, const std::string& text, int chars) {
    std::size_t n = std::min(text.size(), std::size_t(chars));
    if (n < text.size())
        while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80)
            --n;
    const std::size_t at = out.size();
    out.resize(at + std::size_t(chars), '\0');
    text.copy(out.data() + at, n);
}

void pushVector(std::vector<double>& out, const Eigen::VectorXd& x, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
        out.push_back(Eigen::Index(i) < x.size() ? x[Eigen::Index(i)] : kNaN);
}

void pushValues(std::vector<double>& out, const std::vector<double>& x, std::size_t n, bool ok) {
    for (std::size_t i = 0; i < n; ++i)
        out.push_back(ok && i < x.size() ? x[i] : kNaN);
}

} // namespace

void RecordWriter::Impl::Batch::clear() {
    for (auto* b : {&bStep, &bDofStep, &bApplied, &bThisStep, &bPending, &bRequested, &bEventStep,
                    &bEventElement, &bEventDecision, &bEventProposal})
        b->clear();
    for (auto* b :
         {&bTime, &bDofTime, &bAg, &bU, &bV, &bA, &bDef, &bForce, &bCmd, &bPar, &bSd, &bAux, &bFit,
          &bTracking, &bEventTime, &bEventValues, &bSiteRoundTrip, &bChannels})
        b->clear();
    bAlarms.clear();
    bNotes.clear();
    actuator.clear();
}

void RecordWriter::Impl::Batch::reserve(std::size_t rows, std::size_t nDof, std::size_t nElem,
                                        std::size_t nPar, std::size_t nSite,
                                        std::size_t nChan) {
    for (auto* b : {&bStep, &bDofStep, &bApplied, &bThisStep, &bPending, &bRequested})
        b->reserve(rows);
    for (auto* b : {&bTime, &bDofTime, &bAg, &bAux, &bFit})
        b->reserve(rows);
    for (auto* b : {&bU, &bV, &bA})
        b->reserve(rows * nDof);
    for (auto* b : {&bDef, &bForce, &bCmd})
        b->reserve(rows * nElem);
    for (auto* b : {&bPar, &bSd})
        b->reserve(rows * nPar);
    bTracking.reserve(rows * std::size_t(recordschema::kTrackingColumns));
    bSiteRoundTrip.reserve(rows * nSite);
    bChannels.reserve(rows * nChan);
    actuator.reserve(rows * nElem);
}

void RecordWriter::Impl::writeBuffers(const Batch& b) {
    const hsize_t n = b.bTime.size();
    if (n > 0) {
        step.append(b.bStep.data(), n);
        time.append(b.bTime.data(), n);
        ag.append(b.bAg.data(), n);
        if (!dofsChosen) {
            u.append(b.bU.data(), n);
            v.append(b.bV.data(), n);
            a.append(b.bA.data(), n);
        } else if (const hsize_t kept = b.bDofStep.size(); kept > 0) {
            dofStep.append(b.bDofStep.data(), kept);
            dofTime.append(b.bDofTime.data(), kept);
            u.append(b.bU.data(), kept);
            v.append(b.bV.data(), kept);
            a.append(b.bA.data(), kept);
        }
        def.append(b.bDef.data(), n);
        force.append(b.bForce.data(), n);
        cmd.append(b.bCmd.data(), n);
        if (nSite > 0)
            siteRoundTrip.append(b.bSiteRoundTrip.data(), n);
        if (nChan > 0)
            channels.append(b.bChannels.data(), n);
        actuator.write(b.actuator, n);
        if (layout.updating) {
            par.append(b.bPar.data(), n);
            sd.append(b.bSd.data(), n);
            aux.append(b.bAux.data(), n);
            fit.append(b.bFit.data(), n);
            applied.append(b.bApplied.data(), n);
            thisStep.append(b.bThisStep.data(), n);
            pending.append(b.bPending.data(), n);
            tracking.append(b.bTracking.data(), n);
            requested.append(b.bRequested.data(), n);
        }
    }
    writeLogs(b);
    h5::check(H5Fflush(file.get(), H5F_SCOPE_GLOBAL), path, "cannot be flushed");
    flushed += int(n);
    alarmsFlushed += int(b.bAlarms.size());
}

void RecordWriter::Impl::writeLogs(const Batch& b) {
    if (!b.bAlarms.empty()) {
        std::vector<double> t;
        std::vector<int> s;
        std::vector<char> sev, kind, msg, code;
        for (const Alarm& al : b.bAlarms) {
            t.push_back(al.time);
            s.push_back(al.step);
            putFixed(sev, alarmSeverityName(al.severity), recordschema::kSeverityChars);
            putFixed(kind, alarmKindName(al.kind), recordschema::kKindChars);
            putFixed(msg, al.message, recordschema::kMessageChars);
            putFixed(code, al.code, recordschema::kKindChars);
        }
        const hsize_t m = b.bAlarms.size();
        alarmTime.append(t.data(), m);
        alarmStep.append(s.data(), m);
        alarmSeverity.append(sev.data(), m);
        alarmKind.append(kind.data(), m);
        alarmMessage.append(msg.data(), m);
        alarmCode.append(code.data(), m);
    }
    if (!b.bEventStep.empty() && layout.updating) {
        const hsize_t m = b.bEventStep.size();
        eventStep.append(b.bEventStep.data(), m);
        eventTime.append(b.bEventTime.data(), m);
        eventElement.append(b.bEventElement.data(), m);
        eventValues.append(b.bEventValues.data(), m);
        eventDecision.append(b.bEventDecision.data(), m);
        eventProposal.append(b.bEventProposal.data(), m);
    }
    if (!b.bNotes.empty()) {
        std::vector<double> t;
        std::vector<int> s;
        std::vector<char> text;
        for (const RecordNote& note : b.bNotes) {
            t.push_back(note.time);
            s.push_back(note.step);
            putFixed(text, note.text, recordschema::kNoteChars);
        }
        const hsize_t m = b.bNotes.size();
        noteTime.append(t.data(), m);
        noteStep.append(s.data(), m);
        noteText.append(text.data(), m);
        notesFlushed += int(m);
    }
}

bool RecordWriter::Impl::flush(bool synchronous) {
    lastFlush = Clock::now();
    if (failed || closed)
        return !failed;
    if (tracked && tracked->size() > alarmsSeen) {
        fill.bAlarms.insert(fill.bAlarms.end(), tracked->begin() + long(alarmsSeen),
                            tracked->end());
        alarmsSeen = tracked->size();
    }
    thread->wait();       // back-pressure: the previous batch is on disk before the next goes
    std::swap(fill, out); // the vectors' buffers change hands, capacities kept
    thread->start();
    if (synchronous)
        thread->wait();
    return !failed;
}

void RecordWriter::Impl::writeOut() {
    if (!failed) {
        try {
            const h5::QuietErrors quiet;
            writeBuffers(out);
        } catch (const std::exception& e) {
            error = e.what();
            failed = true;
        }
    }
    out.clear();
}

std::vector<h5::Extendible*> RecordWriter::Impl::datasets() {
    return {&step,
            &time,
            &ag,
            &u,
            &v,
            &a,
            &def,
            &force,
            &cmd,
            &par,
            &sd,
            &aux,
            &fit,
            &applied,
            &thisStep,
            &pending,
            &tracking,
            &requested,
            &eventStep,
            &eventTime,
            &eventElement,
            &eventValues,
            &eventDecision,
            &eventProposal,
            &alarmTime,
            &alarmStep,
            &alarmSeverity,
            &alarmKind,
            &alarmMessage,
            &alarmCode,
            &noteTime,
            &noteStep,
            &noteText,
            &siteRoundTrip,
            &channels,
            &dofStep,
            &dofTime};
}

int RecordWriter::batchRowsFor(std::size_t nDof, std::size_t nElem) {
    const long width = long(std::max<std::size_t>(3 * (nDof + nElem), 1));
    const long byValues = std::max(kMaxBufferedValues / width, 1L);
    const long rows = std::min<long>(kMaxBufferedRows, byValues);
    const long chunk = recordschema::chunkRowsFor(int(std::max(nDof, nElem)), int(sizeof(double)));
    return int(rows >= chunk ? rows / chunk * chunk : rows);
}

RecordWriter::RecordWriter(const std::string& path, const RunLayout& layout,
                           const RecordStart& start)
    : m_d(std::make_unique<Impl>()) {
    m_d->path = path;
    m_d->layout = layout;
    m_d->nDof = layout.dofNames.size();
    m_d->keptDofs = start.dofRecording.dofs;
    m_d->every = std::max(1, start.dofRecording.every);
    if (!DofRecording{m_d->keptDofs, 1}.validFor(m_d->nDof))
        throw RecordError(path +
                          ": cannot be created (the DOFs to record must be "
                          "ascending indices below " +
                          std::to_string(m_d->nDof) + ")");
    if (m_d->keptDofs.size() == m_d->nDof)
        m_d->keptDofs.clear(); // every DOF
    m_d->dofsChosen = !m_d->keptDofs.empty() || m_d->every > 1;
    m_d->nKept = m_d->keptDofs.empty() ? m_d->nDof : m_d->keptDofs.size();
    m_d->nElem = layout.elements.size();
    m_d->nPar = layout.updating ? layout.updating->parameters.size() : 0;
    m_d->nSite = layout.sites.size();
    m_d->nChan = layout.channels.size();
    const h5::QuietErrors quiet;
    m_d->create(start); // on a throw, Impl's handles close the partial file
    // The full record's batch (chosen DOFs: no more memory, the element chunks as before).
    m_d->batchRows = batchRowsFor(m_d->nDof, m_d->nElem);
    const std::size_t rows = std::size_t(m_d->batchRows);
    for (Impl::Batch* b : {&m_d->fill, &m_d->out})
        b->reserve(rows, m_d->nKept, m_d->nElem, m_d->nPar, m_d->nSite, m_d->nChan);
    m_d->thread = std::make_unique<RecordThread>([d = m_d.get()] { d->writeOut(); });
}

RecordWriter::~RecordWriter() {
    finish();
}

void RecordWriter::onStep(const StepRecord& r) {
    Impl& d = *m_d;
    ++d.received;
    if (d.failed || d.closed)
        return;
    d.fill.bStep.push_back(r.step);
    d.fill.bTime.push_back(r.time);
    d.fill.bAg.push_back(r.groundAcceleration);
    if (!d.dofsChosen) {
        pushVector(d.fill.bU, r.u, d.nDof);
        pushVector(d.fill.bV, r.v, d.nDof);
        pushVector(d.fill.bA, r.a, d.nDof);
    } else if (r.step % d.every == 0) {
        d.bufferChosenDofs(r);
    }
    for (std::size_t i = 0; i < d.nElem; ++i) {
        const ElementSample s = i < r.elements.size() ? r.elements[i] : ElementSample{};
        d.fill.bDef.push_back(s.deformation);
        d.fill.bForce.push_back(s.force);
        d.fill.bCmd.push_back(s.commanded);
    }
    pushValues(d.fill.bSiteRoundTrip, r.siteRoundTrips, d.nSite, true);
    pushValues(d.fill.bChannels, r.channels, d.nChan, true);
    d.actuator.buffer(r, d.fill.actuator);
    if (d.layout.updating) {
        const UpdatingSample& up = r.updating;
        pushValues(d.fill.bPar, up.parameters, d.nPar, r.hasUpdating);
        pushValues(d.fill.bSd, up.stddev, d.nPar, r.hasUpdating);
        d.fill.bAux.push_back(r.hasUpdating ? up.auxiliaryForce : kNaN);
        d.fill.bFit.push_back(r.hasUpdating ? up.fitError : kNaN);
        d.fill.bApplied.push_back(r.hasUpdating ? up.appliedUpdates : 0);
        d.fill.bThisStep.push_back(r.hasUpdating ? up.updatesThisStep : 0);
        d.fill.bPending.push_back(r.hasUpdating ? up.pendingProposals : 0);
        d.fill.bTracking.push_back(r.hasUpdating ? up.tracking.j1 : kNaN);
        d.fill.bTracking.push_back(r.hasUpdating ? up.tracking.j2 : kNaN);
        d.fill.bTracking.push_back(r.hasUpdating ? up.tracking.j3 : kNaN);
        d.fill.bRequested.push_back(r.hasUpdating && up.updateRequested ? 1 : 0);
        if (r.hasUpdating)
            for (const auto* events : {&up.applied, &up.decided})
                for (const UpdateEvent& ev : *events)
                    d.bufferEvent(ev);
    }
    // A batch ends where a chunk does (row counts that are multiples of batchRows), also after
    // a flush by time cut the previous one short: otherwise every later chunk would be
    // written (and checksummed) twice, once partly filled.
    if (d.received % d.batchRows == 0 ||
        Clock::now() - d.lastFlush >= std::chrono::duration<double>(kFlushInterval))
        d.flush(false);
}

void RecordWriter::writeAlarms(const std::vector<Alarm>& alarms) {
    Impl& d = *m_d;
    // A vector other than the tracked one: its own count is the number already seen.
    if (alarms.size() > d.alarmsSeen) {
        d.fill.bAlarms.insert(d.fill.bAlarms.end(), alarms.begin() + long(d.alarmsSeen),
                              alarms.end());
        d.alarmsSeen = alarms.size();
    }
}

void RecordWriter::trackAlarms(const std::vector<Alarm>* alarms) {
    m_d->tracked = alarms;
}

void RecordWriter::Impl::bufferChosenDofs(const StepRecord& r) {
    fill.bDofStep.push_back(r.step);
    fill.bDofTime.push_back(r.time);
    const auto at = [](const Eigen::VectorXd& x, int k) { return k < x.size() ? x[k] : kNaN; };
    const bool all = keptDofs.empty();
    for (std::size_t j = 0; j < nKept; ++j)
        fill.bU.push_back(at(r.u, all ? int(j) : keptDofs[j]));
    for (std::size_t j = 0; j < nKept; ++j)
        fill.bV.push_back(at(r.v, all ? int(j) : keptDofs[j]));
    for (std::size_t j = 0; j < nKept; ++j)
        fill.bA.push_back(at(r.a, all ? int(j) : keptDofs[j]));
}

void RecordWriter::Impl::bufferEvent(const UpdateEvent& ev) {
    int element = -1; // the target's column in /elements
    for (std::size_t j = 0; j < layout.elements.size(); ++j)
        if (layout.elements[j].name == ev.element)
            element = int(j);
    fill.bEventStep.push_back(ev.step);
    fill.bEventTime.push_back(ev.time);
    fill.bEventElement.push_back(element);
    fill.bEventDecision.push_back(int(ev.decision));
    fill.bEventProposal.push_back(ev.proposal);
    for (const std::string& name : layout.updating->parameters) {
        const auto k = ev.parameters.find(name);
        fill.bEventValues.push_back(k && *k < ev.applied.size() ? ev.applied[*k] : kNaN);
    }
}

bool RecordWriter::Impl::hasBuffered() const {
    return !fill.bTime.empty() || !fill.bAlarms.empty() || !fill.bNotes.empty() ||
           !fill.bEventStep.empty() || (tracked && tracked->size() > alarmsSeen);
}

void RecordWriter::flushIfDue() {
    const Impl& d = *m_d;
    if (d.hasBuffered() &&
        Clock::now() - d.lastFlush >= std::chrono::duration<double>(kFlushInterval))
        m_d->flush(false);
}

void RecordWriter::addNote(double time, int step, const std::string& text) {
    if (!m_d->failed && !m_d->closed)
        m_d->fill.bNotes.push_back({time, step, text});
}

bool RecordWriter::flush() {
    return m_d->flush(true);
}

bool RecordWriter::finish() {
    Impl& d = *m_d;
    if (d.closed)
        return !d.failed;
    d.flush(true);
    d.closed = true;
    d.thread.reset(); // joined: from here on HDF5 is used by this thread only
    const h5::QuietErrors quiet;
    for (h5::Extendible* x : d.datasets())
        *x = h5::Extendible();
    d.actuator.close();
    for (h5::Id* t : {&d.severityType, &d.kindType, &d.messageType, &d.noteType})
        t->reset();
    if (d.file.valid() && H5Fclose(d.file.release()) < 0 && !d.failed) {
        d.failed = true;
        d.error = d.path + ": cannot be closed (HDF5: " + h5::errorText() + ")";
    }
    return !d.failed;
}

bool RecordWriter::appendNote(const std::string& path, double time, int step,
                              const std::string& text, std::string* error) {
    const h5::QuietErrors quiet;
    try {
        const h5::Id file = h5::check(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), path,
                                      "cannot be opened to add a note");
        const auto appendRow = [&](const char* name, hid_t memType, const void* value) {
            const h5::Id dset = h5::check(H5Dopen2(file.get(), name, H5P_DEFAULT), path,
                                          std::string("has no ") + name);
            const h5::Id space = h5::check(H5Dget_space(dset.get()), path, "no dataspace");
            hsize_t rows = 0;
            H5Sget_simple_extent_dims(space.get(), &rows, nullptr);
            const hsize_t grown = rows + 1;
            h5::check(H5Dset_extent(dset.get(), &grown), path, "cannot extend the notes");
            const h5::Id fileSpace = h5::check(H5Dget_space(dset.get()), path, "no dataspace");
            const hsize_t one = 1;
            h5::check(
                H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, &rows, nullptr, &one, nullptr),
                path, "cannot select the new note");
            const h5::Id memSpace =
                h5::check(H5Screate_simple(1, &one, nullptr), path, "no dataspace");
            h5::check(
                H5Dwrite(dset.get(), memType, memSpace.get(), fileSpace.get(), H5P_DEFAULT, value),
                path, "cannot write the note");
        };
        std::vector<char> fixed;
        putFixed(fixed, text, recordschema::kNoteChars);
        const h5::Id noteType = h5::fixedStringType(recordschema::kNoteChars);
        appendRow("/notes/time", H5T_NATIVE_DOUBLE, &time);
        appendRow("/notes/step", H5T_NATIVE_INT, &step);
        appendRow("/notes/text", noteType.get(), fixed.data());
        if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0)
            throw RecordError(path + ": the note could not be written (HDF5: " + h5::errorText() +
                              ")");
        return true;
    } catch (const std::exception& e) {
        if (error)
            *error = e.what();
        return false;
    }
}

bool RecordWriter::ok() const {
    return !m_d->failed;
}
const std::string& RecordWriter::error() const {
    static const std::string none;
    return m_d->failed ? m_d->error : none; // `error` is complete once `failed` is set
}
const std::string& RecordWriter::path() const {
    return m_d->path;
}
int RecordWriter::rowsReceived() const {
    return m_d->received;
}
int RecordWriter::rowsFlushed() const {
    return m_d->flushed;
}
int RecordWriter::notesFlushed() const {
    return m_d->notesFlushed;
}

int RecordWriter::alarmsFlushed() const {
    return m_d->alarmsFlushed;
}

} // namespace hsmu
