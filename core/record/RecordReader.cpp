#include "core/record/RecordReader.h"

#include "core/record/Hdf5Util.h"
#include "core/record/RecordChecksum.h"
#include "core/record/RecordProbe.h"
#include "core/record/RecordReaderImpl.h"
#include "core/record/RecordSchema.h"

#include <algorithm>
#include <filesystem>

namespace hsmu {

namespace recordreader {

void appendRows(Eigen::VectorXd& out, const Column& c, hsize_t r0, hsize_t r1,
                const std::string& w) {
    out.conservativeResize(Eigen::Index(r1));
    c.read(r0, r1, H5T_NATIVE_DOUBLE, out.data() + r0, w);
}

void appendRows(std::vector<int>& out, const Column& c, hsize_t r0, hsize_t r1,
                const std::string& w) {
    out.resize(r1);
    c.read(r0, r1, H5T_NATIVE_INT, out.data() + r0, w);
}

/// Rows [r0, r1) of out from file rows [r0 + offset, r1 + offset).
void appendRows(Eigen::MatrixXd& out, const Column& c, hsize_t r0, hsize_t r1, const std::string& w,
                hsize_t offset) {
    using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    RowMajor block(Eigen::Index(r1 - r0), c.cols);
    c.read(r0 + offset, r1 + offset, H5T_NATIVE_DOUBLE, block.data(), w);
    out.conservativeResize(Eigen::Index(r1), c.cols);
    out.bottomRows(block.rows()) = block;
}

} // namespace recordreader

using recordreader::appendRows;


void RecordReader::Impl::open() {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw RecordError(path + ": cannot be opened (no such file)");
    if (H5Fis_hdf5(path.c_str()) <= 0)
        throw RecordError(path + ": not an HSMU record (not an HDF5 file)");
    hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY | H5F_ACC_SWMR_READ, H5P_DEFAULT);
    swmr = id >= 0;
    if (id < 0) // an older format (not written by us) or a damaged file
        id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    file = h5::check(id, path, "damaged or truncated record (HDF5 cannot open it)");
}

Column RecordReader::Impl::column(const char* name, int cols) {
    Column c;
    c.name = name;
    c.cols = cols;
    c.dset = h5::check(H5Dopen2(file.get(), name, H5P_DEFAULT), path,
                       std::string("damaged or truncated record (no dataset ") + name + ")");
    const h5::Id space = h5::check(H5Dget_space(c.dset.get()), path, "no dataspace");
    const int rank = H5Sget_simple_extent_ndims(space.get());
    hsize_t dims[2] = {0, 0};
    if (rank != (cols >= 0 ? 2 : 1) || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 ||
        (cols >= 0 && dims[1] != hsize_t(cols)))
        throw RecordError(path + ": damaged record (" + name + " has an unexpected shape)");
    return c;
}

std::vector<Column*> RecordReader::Impl::stepColumns() {
    std::vector<Column*> c = {&step, &time, &ag, &def, &force, &cmd};
    if (!dofsChosen)
        for (Column* x : {&u, &v, &a})
            c.push_back(x);
    if (actuator)
        for (Column* x : {&actCmd, &actMeasured, &actTicks, &actFlags})
            c.push_back(x);
    if (data.layout.updating)
        for (Column* x : {&par, &sd, &aux, &fit, &applied, &thisStep, &pending})
            c.push_back(x);
    if (data.layout.updating && v2)
        for (Column* x : {&tracking, &requested})
            c.push_back(x);
    if (!data.layout.channels.empty())
        c.push_back(&channels);
    if (!data.layout.sites.empty())
        c.push_back(&siteRoundTrip);
    return c;
}

std::vector<Column*> RecordReader::Impl::dofColumns() {
    if (!dofsChosen)
        return {};
    return {&dofStep, &dofTime, &u, &v, &a};
}

void RecordReader::Impl::refreshDatasets() {
    if (!swmr)
        return;
    auto columns = stepColumns();
    for (Column* c : logColumns())
        columns.push_back(c);
    for (Column* c : dofColumns())
        columns.push_back(c);
    for (Column* c : columns)
        h5::check(H5Drefresh(c->dset.get()), path,
                  "damaged or truncated record (cannot refresh " + c->name + ")");
}

std::vector<Column*> RecordReader::Impl::logColumns() {
    std::vector<Column*> c = {&alarmTime, &alarmStep, &alarmSeverity, &alarmKind, &alarmMessage};
    if (alarmCode.dset.valid())
        c.push_back(&alarmCode);
    if (v2) {
        for (Column* x : {&noteTime, &noteStep, &noteText})
            c.push_back(x);
        if (data.layout.updating)
            for (Column* x : {&eventStep, &eventTime, &eventElement, &eventValues})
                c.push_back(x);
        if (data.layout.updating && eventDecision.dset.valid())
            for (Column* x : {&eventDecision, &eventProposal})
                c.push_back(x);
    }
    return c;
}

void RecordReader::Impl::readMetadata() {
    const hid_t root = file.get();
    const std::string& w = path;
    if (!h5::hasAttr(root, "schema_version"))
        throw RecordError(path + ": not an HSMU record (no schema_version attribute)");
    RecordMetadata& m = data.meta;
    m.schemaVersion = h5::readIntAttr(root, "schema_version", w);
    if (m.schemaVersion > recordschema::kVersion)
        throw RecordError(path + ": schema version " + std::to_string(m.schemaVersion) +
                          " is newer than this program's " +
                          std::to_string(recordschema::kVersion));
    m.program = h5::readStringAttr(root, "program", w);
    m.programVersion = h5::readStringAttr(root, "program_version", w);
    m.startTime = h5::readStringAttr(root, "start_time", w);
    m.configuration = h5::readStringAttr(root, "configuration", w);
    m.configName = h5::readStringAttr(root, "config_name", w);
    m.operatorNotes = h5::readStringAttr(root, "operator_notes", w);
    m.dt = h5::readDoubleAttr(root, "dt", w);
    if (h5::hasAttr(root, "run"))
        m.run = h5::readStringAttr(root, "run", w);
    if (h5::hasAttr(root, "numerics"))
        m.numerics = h5::readStringAttr(root, "numerics", w);

    RunLayout& layout = data.layout;
    {
        const h5::Id g =
            h5::check(H5Gopen2(root, "dofs", H5P_DEFAULT), w, "damaged record (no group /dofs)");
        layout.dofNames = h5::readStringsAttr(g.get(), "names", w);
        // Chosen or decimated DOFs (docs/recording.md): absent in a record of every DOF.
        dofsChosen = h5::hasAttr(g.get(), "dof_indices");
        if (dofsChosen) {
            DofRecording& r = m.dofRecording;
            r.dofs = h5::readIntsAttr(g.get(), "dof_indices", w);
            r.every = h5::readIntAttr(g.get(), "every", w);
            if (!DofRecording{r.dofs, 1}.validFor(layout.dofNames.size()))
                throw RecordError(path + ": damaged record (/dofs dof_indices)");
            if (r.every < 1 || r.dofs.empty())
                throw RecordError(path + ": damaged record (/dofs every or dof_indices)");
            if (r.dofs.size() == layout.dofNames.size())
                r.dofs.clear(); // every DOF, decimated
        }
    }
    const int nDof = dofsChosen && !m.dofRecording.dofs.empty() ? int(m.dofRecording.dofs.size())
                                                                : int(layout.dofNames.size());
    {
        const h5::Id g = h5::check(H5Gopen2(root, "elements", H5P_DEFAULT), w,
                                   "damaged record (no group /elements)");
        const auto names = h5::readStringsAttr(g.get(), "names", w);
        const auto types = h5::readStringsAttr(g.get(), "types", w);
        const auto experimental = h5::readIntsAttr(g.get(), "experimental", w);
        const auto nonlinear = h5::readIntsAttr(g.get(), "nonlinear", w);
        def = column("/elements/deformation", int(names.size()));
        force = column("/elements/force", int(names.size()));
        const auto defUnits = h5::readStringsAttr(def.dset.get(), "units", w);
        const auto forceUnits = h5::readStringsAttr(force.dset.get(), "units", w);
        const std::size_t n = names.size();
        if (types.size() != n || experimental.size() != n || nonlinear.size() != n ||
            defUnits.size() != n || forceUnits.size() != n)
            throw RecordError(path + ": damaged record (element attributes disagree)");
        for (std::size_t i = 0; i < n; ++i)
            layout.elements.push_back({names[i],
                                       types[i],
                                       experimental[i] != 0,
                                       nonlinear[i] != 0,
                                       {defUnits[i], forceUnits[i]}});
    }
    const int nElem = int(layout.elements.size());
    step = column("/steps/step", -1);
    time = column("/steps/time", -1);
    ag = column("/steps/ground_acceleration", -1);
    u = column("/dofs/u", nDof);
    v = column("/dofs/v", nDof);
    a = column("/dofs/a", nDof);
    if (dofsChosen) {
        dofStep = column("/dofs/step", -1);
        dofTime = column("/dofs/time", -1);
    }
    cmd = column("/elements/commanded", nElem);
    if (H5Lexists(root, "sites", H5P_DEFAULT) > 0) {
        const h5::Id g =
            h5::check(H5Gopen2(root, "sites", H5P_DEFAULT), w, "damaged record (no group /sites)");
        layout.sites = h5::readStringsAttr(g.get(), "names", w);
        if (h5::hasAttr(g.get(), "security"))
            m.siteSecurity = h5::readStringsAttr(g.get(), "security", w);
        siteRoundTrip = column("/sites/round_trip", int(layout.sites.size()));
    }
    actuator = H5Lexists(root, "/elements/actuator", H5P_DEFAULT) > 0;
    if (actuator) {
        actCmd = column("/elements/actuator/commanded", nElem);
        actMeasured = column("/elements/actuator/measured", nElem);
        actTicks = column("/elements/actuator/held_ticks", nElem);
        actFlags = column("/elements/actuator/flags", nElem);
    }
    if (H5Lexists(root, "/elements/channels", H5P_DEFAULT) > 0) {
        const h5::Id d = h5::check(H5Dopen2(root, "/elements/channels", H5P_DEFAULT), w,
                                   "damaged record (no dataset /elements/channels)");
        const auto owner = h5::readStringsAttr(d.get(), "elements", w);
        const auto names = h5::readStringsAttr(d.get(), "names", w);
        const auto units = h5::readStringsAttr(d.get(), "units", w);
        if (names.size() != owner.size() || units.size() != owner.size())
            throw RecordError(path + ": damaged record (channel attributes disagree)");
        for (std::size_t i = 0; i < owner.size(); ++i)
            layout.channels.push_back({owner[i], names[i], units[i]});
        channels = column("/elements/channels", int(owner.size()));
    }
    if (H5Lexists(root, "updating", H5P_DEFAULT) > 0) {
        const h5::Id g = h5::check(H5Gopen2(root, "updating", H5P_DEFAULT), w,
                                   "damaged record (no group /updating)");
        UpdatingInfo info;
        info.specimen = h5::readStringAttr(g.get(), "specimen", w);
        info.method = h5::readStringAttr(g.get(), "method", w);
        info.parameters = h5::readStringsAttr(g.get(), "names", w);
        info.units.deformation = h5::readStringAttr(g.get(), "deformation_units", w);
        info.units.force = h5::readStringAttr(g.get(), "force_units", w);
        if (h5::hasAttr(g.get(), "basic_dof"))
            info.basicDof = h5::readStringAttr(g.get(), "basic_dof", w);
        const int nPar = int(info.parameters.size());
        layout.updating = std::move(info);
        par = column("/updating/parameters", nPar);
        sd = column("/updating/stddev", nPar);
        aux = column("/updating/auxiliary_force", -1);
        fit = column("/updating/fit_error", -1);
        applied = column("/updating/applied_updates", -1);
        thisStep = column("/updating/updates_this_step", -1);
        pending = column("/updating/pending_proposals", -1);
        if (m.schemaVersion >= 2) {
            tracking = column("/updating/tracking", recordschema::kTrackingColumns);
            requested = column("/updating/update_requested", -1);
            eventStep = column("/updating/events/step", -1);
            eventTime = column("/updating/events/time", -1);
            eventElement = column("/updating/events/element", -1);
            eventValues = column("/updating/events/values", nPar);
            // Optional (added later): what became of each offer, and its proposal id.
            if (H5Lexists(root, "/updating/events/decision", H5P_DEFAULT) > 0 &&
                H5Lexists(root, "/updating/events/proposal", H5P_DEFAULT) > 0) {
                eventDecision = column("/updating/events/decision", -1);
                eventProposal = column("/updating/events/proposal", -1);
                decisionCodes = h5::readStringsAttr(eventDecision.dset.get(), "codes", w);
            }
        }
    }
    v2 = m.schemaVersion >= 2;
    if (v2) {
        noteTime = column("/notes/time", -1);
        noteStep = column("/notes/step", -1);
        noteText = column("/notes/text", -1);
    }
    alarmTime = column("/alarms/time", -1);
    alarmStep = column("/alarms/step", -1);
    alarmSeverity = column("/alarms/severity", -1);
    alarmKind = column("/alarms/kind", -1);
    alarmMessage = column("/alarms/message", -1);
    if (H5Lexists(root, "/alarms/code", H5P_DEFAULT) > 0) // optional (added later)
        alarmCode = column("/alarms/code", -1);
    if (h5::hasAttr(root, "metadata_checksum") &&
        h5::readStringAttr(root, "metadata_checksum", w) != recordMetadataChecksum(m, layout))
        throw RecordError(path + ": damaged record (the metadata checksum does not match: "
                                 "attributes or names were altered)");
}


int RecordReader::Impl::readNewRows() {
    const auto columns = stepColumns();
    hsize_t n = columns.front()->rows();
    for (const Column* c : columns)
        n = std::min(n, c->rows());
    const hsize_t r0 = hsize_t(data.rows());
    readNewDofRows();
    if (n <= r0)
        return 0;
    const std::string& w = path;
    appendRows(data.steps, step, r0, n, w);
    appendRows(data.time, time, r0, n, w);
    appendRows(data.groundAcceleration, ag, r0, n, w);
    if (!dofsChosen) {
        appendRows(data.u, u, r0, n, w);
        appendRows(data.v, v, r0, n, w);
        appendRows(data.a, a, r0, n, w);
    }
    appendRows(data.deformation, def, r0, n, w);
    appendRows(data.force, force, r0, n, w);
    appendRows(data.commanded, cmd, r0, n, w);
    if (!data.layout.sites.empty())
        appendRows(data.siteRoundTrip, siteRoundTrip, r0, n, w);
    if (!data.layout.channels.empty())
        appendRows(data.channels, channels, r0, n, w);
    if (actuator) {
        appendRows(data.actuatorCommanded, actCmd, r0, n, w);
        appendRows(data.actuatorMeasured, actMeasured, r0, n, w);
        appendRows(data.heldTicks, actTicks, r0, n, w);
        appendRows(data.actuatorFlags, actFlags, r0, n, w);
    }
    if (data.layout.updating) {
        appendRows(data.parameters, par, r0, n, w);
        appendRows(data.stddev, sd, r0, n, w);
        appendRows(data.auxiliaryForce, aux, r0, n, w);
        appendRows(data.fitError, fit, r0, n, w);
        appendRows(data.appliedUpdates, applied, r0, n, w);
        appendRows(data.updatesThisStep, thisStep, r0, n, w);
        appendRows(data.pendingProposals, pending, r0, n, w);
        if (v2) {
            appendRows(data.tracking, tracking, r0, n, w);
            appendRows(data.updateRequested, requested, r0, n, w);
        }
    }
    return int(n - r0);
}

void RecordReader::Impl::readNewDofRows() {
    const auto columns = dofColumns();
    if (columns.empty())
        return;
    hsize_t n = columns.front()->rows();
    for (const Column* c : columns)
        n = std::min(n, c->rows());
    const hsize_t r0 = hsize_t(data.dofSteps.size());
    if (n <= r0)
        return;
    const std::string& w = path;
    appendRows(data.dofSteps, dofStep, r0, n, w);
    appendRows(data.dofTimes, dofTime, r0, n, w);
    appendRows(data.u, u, r0, n, w);
    appendRows(data.v, v, r0, n, w);
    appendRows(data.a, a, r0, n, w);
}


void RecordReader::Impl::walkChunkIndexes() {
    std::vector<Column*> all = stepColumns();
    for (Column* c : logColumns())
        all.push_back(c);
    for (Column* c : dofColumns())
        all.push_back(c);
    for (Column* c : all) {
        const std::string what = "damaged or truncated record (the chunk index of " + c->name;
        hsize_t chunks = 0;
        const h5::Id space(H5Dget_space(c->dset.get()));
        if (!space.valid() || H5Dget_num_chunks(c->dset.get(), space.get(), &chunks) < 0)
            throw RecordError(path + ": " + what + " cannot be read)");
        for (hsize_t i = 0; i < chunks; ++i) {
            haddr_t address = HADDR_UNDEF;
            hsize_t size = 0;
            if (H5Dget_chunk_info(c->dset.get(), space.get(), i, nullptr, nullptr, &address, &size) < 0)
                throw RecordError(path + ": " + what + " cannot be read)");
            (void)address; // a live (SWMR) record's chunks may lie past the size on disk yet
            (void)size;
        }
    }
}

RecordReader::RecordReader(const std::string& path) : m_d(std::make_unique<Impl>()) {
    m_d->path = path;
    {
        // First a walk of the file's metadata in a child process with a deadline (every
        // object, attribute and chunk index; the logs' few rows read): a damaged file must fail
        // within kRecordOpenDeadline, never hang this process inside HDF5. The chunks' data is
        // then read here, each under its Fletcher32 checksum (a damaged chunk fails, no hang).
        std::error_code ec;
        if (!std::filesystem::is_regular_file(path, ec))
            throw RecordError(path + ": cannot be opened (no such file)");
        const auto fail = probeRecord(path, kRecordOpenDeadline, [](const std::string& p) {
            Impl d;
            d.path = p;
            const h5::QuietErrors quiet;
            d.open();
            d.readMetadata();
            d.walkChunkIndexes();
            d.readNewAlarms();
            d.readNewEvents();
            d.readNewNotes();
        });
        if (fail)
            throw RecordError(*fail);
    }
    const h5::QuietErrors quiet;
    m_d->open();
    m_d->readMetadata();
    // HDF5 shares a file already open in this process (an earlier reader of a record being
    // written): its datasets' cached extents are that reader's, so refresh them first.
    m_d->refreshDatasets();
    m_d->readNewRows();
    m_d->readNewAlarms();
    m_d->readNewEvents();
    m_d->readNewNotes();
}

RecordReader::~RecordReader() = default;

const RecordData& RecordReader::data() const {
    return m_d->data;
}
const std::string& RecordReader::path() const {
    return m_d->path;
}
bool RecordReader::swmr() const {
    return m_d->swmr;
}

int RecordReader::refresh() {
    const h5::QuietErrors quiet;
    m_d->refreshDatasets();
    const int added = m_d->readNewRows();
    m_d->readNewAlarms();
    m_d->readNewEvents();
    m_d->readNewNotes();
    return added;
}

} // namespace hsmu
