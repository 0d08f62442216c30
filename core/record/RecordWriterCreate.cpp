// RecordWriter's file creation: the file (created under a temporary name, renamed once its
// header is on disk), the root attributes and every group and dataset of docs/recording.md.

#include "core/record/RecordWriterImpl.h"

#include <cmath>
#include <ctime>
#include <filesystem>
#include <numeric>

namespace hsmu {

namespace {

std::string isoUtcNow() {
    const std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

} // namespace

void RecordWriter::Impl::create(const RecordStart& start) {
    const std::string& w = path;
    const h5::Id fapl = h5::check(H5Pcreate(H5P_FILE_ACCESS), w, "cannot make a property list");
    h5::check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_LATEST, H5F_LIBVER_LATEST), w,
              "cannot select the latest file format");
    // Each dataset's chunk cache holds one and a half of the widest matrix's row band (its
    // chunks being filled: every column part of chunkShapeFor's 2-D chunks, so that a partial
    // batch's chunks are not read back), not HDF5's default 1 MiB: rows are only appended, so a written chunk is never
    // read back, and with 1 MiB a 31,160-step SDOF run kept 3.2 MB of written chunks (issue
    // 27). Set on the file: H5Fstart_swmr_write() reopens the datasets with the file's cache.
    const long widest = long(std::max({nKept, nElem, nPar, nSite, nChan,
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
    if (dofsChosen)
        meta.dofRecording = {keptDofs, every};
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
        const int n = int(nKept);
        const int rows = recordschema::kChunkRows, z = start.deflate;
        std::vector<std::string> kept = layout.dofNames;
        if (dofsChosen) { // docs/recording.md "Chosen and decimated DOFs"
            if (!keptDofs.empty()) {
                kept.clear();
                for (const int k : keptDofs)
                    kept.push_back(layout.dofNames[std::size_t(k)]);
            }
            std::vector<int> indices = keptDofs;
            if (indices.empty()) { // every DOF, decimated
                indices.resize(nDof);
                std::iota(indices.begin(), indices.end(), 0);
            }
            h5::writeAttr(g.get(), "dof_indices", indices, w);
            h5::writeAttr(g.get(), "every", every, w);
            dofStep = h5::Extendible(g.get(), "step", i32, -1, w);
            dofTime = h5::Extendible(g.get(), "time", f64, -1, w);
            units(dofTime, "s");
        }
        u = h5::Extendible(g.get(), "u", f64, n, w, rows, z);
        v = h5::Extendible(g.get(), "v", f64, n, w, rows, z);
        a = h5::Extendible(g.get(), "a", f64, n, w, rows, z);
        for (auto* d : {&u, &v, &a})
            h5::writeAttr(d->id(), "names", kept, w);
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
        if (nChan > 0) { // the multi-DOF elements' basic DOFs and actuators
            std::vector<std::string> owner, channel, unit;
            for (const ElementChannel& c : layout.channels) {
                owner.push_back(c.element);
                channel.push_back(c.name);
                unit.push_back(c.unit);
            }
            channels = h5::Extendible(g.get(), "channels", f64, int(nChan), w, rows, z);
            h5::writeAttr(channels.id(), "elements", owner, w);
            h5::writeAttr(channels.id(), "names", channel, w);
            h5::writeAttr(channels.id(), "units", unit, w);
        }
    }
    if (layout.updating)
        createUpdating(root);
    if (nSite > 0) {
        // Sites (docs/configuration.md): each step's round trip per site [s].
        const h5::Id g = group("sites");
        h5::writeAttr(g.get(), "names", layout.sites, w);
        if (!start.siteSecurity.empty())
            h5::writeAttr(g.get(), "security", securityOfSites(layout.sites, start.siteSecurity), w);
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
    if (!info.basicDof.empty()) // a link2d's basic DOF (docs/recording.md, /updating)
        h5::writeAttr(g.get(), "basic_dof", info.basicDof, w);
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

} // namespace hsmu
