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

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <filesystem>

namespace hsmu {

namespace {

using Clock = std::chrono::steady_clock;
const double kNaN = std::nan("");

std::string isoUtcNow() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

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

struct RecordWriter::Impl {
    std::string path;
    RunLayout layout;
    std::size_t nDof = 0, nElem = 0, nPar = 0, nSite = 0;
    h5::Id file;
    h5::Id severityType, kindType, messageType, noteType;
    h5::Extendible step, time, ag, u, v, a, def, force, cmd;
    h5::Extendible par, sd, aux, fit, applied, thisStep, pending, tracking, requested;
    h5::Extendible eventStep, eventTime, eventElement, eventValues, eventDecision, eventProposal;
    h5::Extendible alarmTime, alarmStep, alarmSeverity, alarmKind, alarmMessage, alarmCode;
    h5::Extendible noteTime, noteStep, noteText;
    h5::Extendible siteRoundTrip;
    ActuatorColumns actuator; // /elements/actuator

    /// Rows, alarms and notes buffered between two flushes.
    struct Batch {
        std::vector<int> bStep, bApplied, bThisStep, bPending, bRequested, bEventStep,
            bEventElement, bEventDecision, bEventProposal;
        std::vector<double> bTime, bAg, bU, bV, bA, bDef, bForce, bCmd, bPar, bSd, bAux, bFit,
            bTracking, bEventTime, bEventValues, bSiteRoundTrip;
        ActuatorColumns::Rows actuator;
        std::vector<Alarm> bAlarms;
        std::vector<RecordNote> bNotes;

        void clear();
        /// Capacity for `rows` rows, so that appending a row never allocates.
        void reserve(std::size_t rows, std::size_t nDof, std::size_t nElem, std::size_t nPar,
                     std::size_t nSite);
    };
    // `fill` belongs to the stepping thread; `out` to the record thread while it writes it
    // (between RecordThread::start() and the next wait()), to the stepping thread otherwise.
    Batch fill, out;
    std::unique_ptr<RecordThread> thread;

    const std::vector<Alarm>* tracked = nullptr;
    std::size_t alarmsSeen = 0;
    int received = 0;
    std::atomic<int> flushed{0}, alarmsFlushed{0}, notesFlushed{0}; // by the record thread
    std::atomic<bool> failed{false}; // set by the record thread once `error` is written
    bool closed = false;
    std::string error;
    Clock::time_point lastFlush = Clock::now();

    void create(const RecordStart& start);
    void createUpdating(hid_t root);
    void createLogs(hid_t root);
    void writeBuffers(const Batch& b);
    void writeLogs(const Batch& b);
    void writeOut(); // the record thread's job: writes and clears `out`
    bool hasBuffered() const;
    void bufferEvent(const UpdateEvent& ev);
    /// Hands the buffered rows to the record thread; with `synchronous`, waits until they
    /// are on disk.
    bool flush(bool synchronous);
    std::vector<h5::Extendible*> datasets();
};

void RecordWriter::Impl::create(const RecordStart& start) {
    const std::string& w = path;
    const h5::Id fapl = h5::check(H5Pcreate(H5P_FILE_ACCESS), w, "cannot make a property list");
    h5::check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST), w,
              "cannot select the latest file format");
    // Each dataset's chunk cache holds one and a half of the largest chunk (the chunk being
    // filled), not HDF5's default 1 MiB: rows are only appended, so a written chunk is never
    // read back, and with 1 MiB a 31,160-step SDOF run kept 3.2 MB of written chunks (issue
    // 27). Set on the file: H5Fstart_swmr_write() reopens the datasets with the file's cache.
    const long widest = long(std::max({nDof, nElem, nPar, nSite,
                                       std::size_t(recordschema::kTrackingColumns)}));
    const std::size_t chunkBytes = std::size_t(
        long(recordschema::chunkRowsFor(int(widest), int(sizeof(double)))) * widest * 8);
    h5::check(H5Pset_cache(fapl.get(), 0, 521, chunkBytes * 3 / 2 + 1, 1.0), w,
              "cannot size the chunk cache");
    // Created under a temporary name in the same folder and renamed (atomically) once its
    // header is on disk: a file at `path` always reads, even after a kill -9 at any moment
    // (issue 26, D10). The open handle follows the rename.
    const std::string partial = path + ".partial";
    file = h5::check(H5Fcreate(partial.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), w,
                     "cannot be created");
    const hid_t root = file.get();
    h5::writeAttr(root, "schema_version", recordschema::kVersion, w);
    RecordMetadata meta; // what the reader will read back, for the metadata checksum
    meta.program = "HSMU Console";
    meta.programVersion = versionString();
    meta.startTime = isoUtcNow();
    meta.configuration = start.configuration;
    meta.configName = start.configName;
    meta.operatorNotes = start.operatorNotes;
    meta.dt = start.dt;
    meta.run = start.run;
    meta.numerics = std::string("UKF sigma points: ") + BoucWen::fastBatchMathName();
    h5::writeAttr(root, "program", meta.program, w);
    h5::writeAttr(root, "program_version", meta.programVersion, w);
    h5::writeAttr(root, "start_time", meta.startTime, w);
    h5::writeAttr(root, "configuration", meta.configuration, w);
    h5::writeAttr(root, "config_name", meta.configName, w);
    h5::writeAttr(root, "operator_notes", meta.operatorNotes, w);
    h5::writeAttr(root, "dt", meta.dt, w);
    h5::writeAttr(root, "run", meta.run, w);
    h5::writeAttr(root, "numerics", meta.numerics, w);
    h5::writeAttr(root, "metadata_checksum", recordMetadataChecksum(meta, layout), w);

    const auto group = [&](const char* name) {
        return h5::check(H5Gcreate2(root, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), w,
                         std::string("cannot create group ") + name);
    };
    const auto units = [&](const h5::Extendible& d, const std::string& unit) {
        h5::writeAttr(d.id(), "units", unit, w);
    };
    const hid_t f64 = H5T_NATIVE_DOUBLE, i32 = H5T_NATIVE_INT;
    // Memory and file types are both native here: the file keeps the machine's (little
    // endian IEEE) representation, which every reader converts as needed.
    {
        const h5::Id g = group("steps");
        step = h5::Extendible(g.get(), "step", i32, -1, w);
        time = h5::Extendible(g.get(), "time", f64, -1, w);
        ag = h5::Extendible(g.get(), "ground_acceleration", f64, -1, w);
        units(time, "s");
        units(ag, "m/s^2");
    }
    {
        const h5::Id g = group("dofs");
        h5::writeAttr(g.get(), "names", layout.dofNames, w);
        const int n = int(nDof);
        const int rows = recordschema::kChunkRows, z = start.deflate;
        u = h5::Extendible(g.get(), "u", f64, n, w, rows, z);
        v = h5::Extendible(g.get(), "v", f64, n, w, rows, z);
        a = h5::Extendible(g.get(), "a", f64, n, w, rows, z);
        for (auto* d : {&u, &v, &a})
            h5::writeAttr(d->id(), "names", layout.dofNames, w);
        units(u, "m");
        units(v, "m/s");
        units(a, "m/s^2");
    }
    {
        const h5::Id g = group("elements");
        std::vector<std::string> names, types, defUnits, forceUnits;
        std::vector<int> experimental, nonlinear;
        for (const ElementInfo& e : layout.elements) {
            names.push_back(e.name);
            types.push_back(e.type);
            defUnits.push_back(e.units.deformation);
            forceUnits.push_back(e.units.force);
            experimental.push_back(e.experimental ? 1 : 0);
            nonlinear.push_back(e.nonlinear ? 1 : 0);
        }
        h5::writeAttr(g.get(), "names", names, w);
        h5::writeAttr(g.get(), "types", types, w);
        h5::writeAttr(g.get(), "experimental", experimental, w);
        h5::writeAttr(g.get(), "nonlinear", nonlinear, w);
        const int n = int(nElem);
        const int rows = recordschema::kChunkRows, z = start.deflate;
        def = h5::Extendible(g.get(), "deformation", f64, n, w, rows, z);
        force = h5::Extendible(g.get(), "force", f64, n, w, rows, z);
        cmd = h5::Extendible(g.get(), "commanded", f64, n, w, rows, z);
        for (auto* d : {&def, &force, &cmd})
            h5::writeAttr(d->id(), "names", names, w);
        h5::writeAttr(def.id(), "units", defUnits, w);
        h5::writeAttr(force.id(), "units", forceUnits, w);
        h5::writeAttr(cmd.id(), "units", defUnits, w);
        actuator.create(g.get(), names, defUnits, w, start.deflate);
    }
    if (layout.updating)
        createUpdating(root);
    if (nSite > 0) {
        // Sites (docs/configuration.md): each step's round trip per site [s].
        const h5::Id g = group("sites");
        h5::writeAttr(g.get(), "names", layout.sites, w);
        if (!start.siteSecurity.empty()) {
            std::vector<std::string> security;
            for (const std::string& site : layout.sites) {
                std::string value;
                for (const auto& [name, how] : start.siteSecurity)
                    if (name == site)
                        value = how;
                security.push_back(value);
            }
            h5::writeAttr(g.get(), "security", security, w);
        }
        siteRoundTrip = h5::Extendible(g.get(), "round_trip", f64, int(nSite), w);
        h5::writeAttr(siteRoundTrip.id(), "names", layout.sites, w);
        units(siteRoundTrip, "s");
    }
    createLogs(root);
    h5::check(H5Fflush(root, H5F_SCOPE_GLOBAL), w, "cannot be flushed");
    h5::check(H5Fstart_swmr_write(root), w, "cannot start SWMR writing");
    std::error_code ec;
    std::filesystem::rename(partial, path, ec);
    if (ec)
        throw RecordError(path + ": cannot be created (renaming " + partial + ": " + ec.message() +
                          ")");
}

void RecordWriter::Impl::createUpdating(hid_t root) {
    const std::string& w = path;
    const UpdatingInfo& info = *layout.updating;
    const hid_t f64 = H5T_NATIVE_DOUBLE, i32 = H5T_NATIVE_INT;
    const h5::Id g = h5::check(H5Gcreate2(root, "updating", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                               w, "cannot create group updating");
    h5::writeAttr(g.get(), "specimen", info.specimen, w);
    h5::writeAttr(g.get(), "method", info.method, w);
    h5::writeAttr(g.get(), "names", info.parameters, w);
    h5::writeAttr(g.get(), "deformation_units", info.units.deformation, w);
    h5::writeAttr(g.get(), "force_units", info.units.force, w);
    par = h5::Extendible(g.get(), "parameters", f64, int(nPar), w);
    sd = h5::Extendible(g.get(), "stddev", f64, int(nPar), w);
    h5::writeAttr(par.id(), "names", info.parameters, w);
    h5::writeAttr(sd.id(), "names", info.parameters, w);
    aux = h5::Extendible(g.get(), "auxiliary_force", f64, -1, w);
    h5::writeAttr(aux.id(), "units", info.units.force, w);
    fit = h5::Extendible(g.get(), "fit_error", f64, -1, w);
    h5::writeAttr(fit.id(), "units", std::string("1"), w);
    applied = h5::Extendible(g.get(), "applied_updates", i32, -1, w);
    thisStep = h5::Extendible(g.get(), "updates_this_step", i32, -1, w);
    pending = h5::Extendible(g.get(), "pending_proposals", i32, -1, w);
    tracking = h5::Extendible(g.get(), "tracking", f64, recordschema::kTrackingColumns, w);
    h5::writeAttr(tracking.id(), "names", std::vector<std::string>{"j1", "j2", "j3"}, w);
    h5::writeAttr(tracking.id(), "units", std::vector<std::string>{"s", "1", "1"}, w);
    requested = h5::Extendible(g.get(), "update_requested", i32, -1, w);

    const h5::Id e = h5::check(H5Gcreate2(g.get(), "events", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                               w, "cannot create group updating/events");
    // Events can come every step (policy everyStep): per-step chunks, not the alarms' small ones.
    const int chunk = recordschema::kChunkRows;
    eventStep = h5::Extendible(e.get(), "step", i32, -1, w, chunk);
    eventTime = h5::Extendible(e.get(), "time", f64, -1, w, chunk);
    h5::writeAttr(eventTime.id(), "units", std::string("s"), w);
    eventElement = h5::Extendible(e.get(), "element", i32, -1, w, chunk);
    eventValues = h5::Extendible(e.get(), "values", f64, int(nPar), w, chunk);
    h5::writeAttr(eventValues.id(), "names", info.parameters, w);
    // What became of each offer (UpdateDecision, language-neutral codes) and its proposal id.
    eventDecision = h5::Extendible(e.get(), "decision", i32, -1, w, chunk);
    std::vector<std::string> codes;
    for (UpdateDecision d :
         {UpdateDecision::Applied, UpdateDecision::Refused, UpdateDecision::Rejected,
          UpdateDecision::NotQueued, UpdateDecision::Superseded})
        codes.emplace_back(updateDecisionName(d));
    h5::writeAttr(eventDecision.id(), "codes", codes, w);
    eventProposal = h5::Extendible(e.get(), "proposal", i32, -1, w, chunk);
}

void RecordWriter::Impl::createLogs(hid_t root) {
    const std::string& w = path;
    const hid_t f64 = H5T_NATIVE_DOUBLE, i32 = H5T_NATIVE_INT;
    const int chunk = recordschema::kAlarmChunkRows;
    {
        const h5::Id g =
            h5::check(H5Gcreate2(root, "alarms", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), w,
                      "cannot create group alarms");
        severityType = h5::fixedStringType(recordschema::kSeverityChars);
        kindType = h5::fixedStringType(recordschema::kKindChars);
        messageType = h5::fixedStringType(recordschema::kMessageChars);
        alarmTime = h5::Extendible(g.get(), "time", f64, -1, w, chunk);
        h5::writeAttr(alarmTime.id(), "units", std::string("s"), w);
        alarmStep = h5::Extendible(g.get(), "step", i32, -1, w, chunk);
        alarmSeverity = h5::Extendible(g.get(), "severity", severityType.get(), -1, w, chunk);
        alarmKind = h5::Extendible(g.get(), "kind", kindType.get(), -1, w, chunk);
        // The message's template (Alarm::code, "" for none): language-neutral, the console
        // shows its own translation of it; /alarms/message keeps the English text.
        alarmCode = h5::Extendible(g.get(), "code", kindType.get(), -1, w, chunk);
        alarmMessage = h5::Extendible(g.get(), "message", messageType.get(), -1, w, chunk);
    }
    const h5::Id g = h5::check(H5Gcreate2(root, "notes", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), w,
                               "cannot create group notes");
    noteType = h5::fixedStringType(recordschema::kNoteChars);
    noteTime = h5::Extendible(g.get(), "time", f64, -1, w, chunk);
    h5::writeAttr(noteTime.id(), "units", std::string("s"), w);
    noteStep = h5::Extendible(g.get(), "step", i32, -1, w, chunk);
    noteText = h5::Extendible(g.get(), "text", noteType.get(), -1, w, chunk);
}

void RecordWriter::Impl::Batch::clear() {
    for (auto* b : {&bStep, &bApplied, &bThisStep, &bPending, &bRequested, &bEventStep,
                    &bEventElement, &bEventDecision, &bEventProposal})
        b->clear();
    for (auto* b : {&bTime, &bAg, &bU, &bV, &bA, &bDef, &bForce, &bCmd, &bPar, &bSd, &bAux, &bFit,
                    &bTracking, &bEventTime, &bEventValues, &bSiteRoundTrip})
        b->clear();
    bAlarms.clear();
    bNotes.clear();
    actuator.clear();
}

void RecordWriter::Impl::Batch::reserve(std::size_t rows, std::size_t nDof, std::size_t nElem,
                                        std::size_t nPar, std::size_t nSite) {
    for (auto* b : {&bStep, &bApplied, &bThisStep, &bPending, &bRequested})
        b->reserve(rows);
    for (auto* b : {&bTime, &bAg, &bAux, &bFit})
        b->reserve(rows);
    for (auto* b : {&bU, &bV, &bA})
        b->reserve(rows * nDof);
    for (auto* b : {&bDef, &bForce, &bCmd})
        b->reserve(rows * nElem);
    for (auto* b : {&bPar, &bSd})
        b->reserve(rows * nPar);
    bTracking.reserve(rows * std::size_t(recordschema::kTrackingColumns));
    bSiteRoundTrip.reserve(rows * nSite);
    actuator.reserve(rows * nElem);
}

void RecordWriter::Impl::writeBuffers(const Batch& b) {
    const hsize_t n = b.bTime.size();
    if (n > 0) {
        step.append(b.bStep.data(), n);
        time.append(b.bTime.data(), n);
        ag.append(b.bAg.data(), n);
        u.append(b.bU.data(), n);
        v.append(b.bV.data(), n);
        a.append(b.bA.data(), n);
        def.append(b.bDef.data(), n);
        force.append(b.bForce.data(), n);
        cmd.append(b.bCmd.data(), n);
        if (nSite > 0)
            siteRoundTrip.append(b.bSiteRoundTrip.data(), n);
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
            &siteRoundTrip};
}

RecordWriter::RecordWriter(const std::string& path, const RunLayout& layout,
                           const RecordStart& start)
    : m_d(std::make_unique<Impl>()) {
    m_d->path = path;
    m_d->layout = layout;
    m_d->nDof = layout.dofNames.size();
    m_d->nElem = layout.elements.size();
    m_d->nPar = layout.updating ? layout.updating->parameters.size() : 0;
    m_d->nSite = layout.sites.size();
    const h5::QuietErrors quiet;
    m_d->create(start); // on a throw, Impl's handles close the partial file
    const std::size_t width = std::max<std::size_t>(3 * (m_d->nDof + m_d->nElem), 1);
    const std::size_t rows =
        std::min<std::size_t>(kMaxBufferedRows, std::size_t(kMaxBufferedValues) / width + 1);
    for (Impl::Batch* b : {&m_d->fill, &m_d->out})
        b->reserve(rows, m_d->nDof, m_d->nElem, m_d->nPar, m_d->nSite);
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
    pushVector(d.fill.bU, r.u, d.nDof);
    pushVector(d.fill.bV, r.v, d.nDof);
    pushVector(d.fill.bA, r.a, d.nDof);
    for (std::size_t i = 0; i < d.nElem; ++i) {
        const ElementSample s = i < r.elements.size() ? r.elements[i] : ElementSample{};
        d.fill.bDef.push_back(s.deformation);
        d.fill.bForce.push_back(s.force);
        d.fill.bCmd.push_back(s.commanded);
    }
    pushValues(d.fill.bSiteRoundTrip, r.siteRoundTrips, d.nSite, true);
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
    if (d.fill.bTime.size() >= std::size_t(kMaxBufferedRows) ||
        long(d.fill.bU.size() * 3 + d.fill.bDef.size() * 3) >= kMaxBufferedValues ||
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
