#pragma once
// RecordReader's inside, shared by its two files: RecordReader.cpp (metadata, step rows, DOF
// rows, chunk walk) and RecordReaderLogs.cpp (alarms, update events, notes). Not installed.

#include "core/record/Hdf5Util.h"
#include "core/record/RecordReader.h"

#include <string>
#include <vector>

namespace hsmu::recordreader {

/// A per-step dataset opened for reading: rows x cols (cols < 0: one-dimensional).
struct Column {
    h5::Id dset;
    int cols = -1;
    std::string name;

    hsize_t rows() const {
        const h5::Id space(H5Dget_space(dset.get()));
        hsize_t dims[2] = {0, 0};
        if (!space.valid() || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0)
            return 0;
        return dims[0];
    }

    /// Rows [r0, r1) into out (row-major), memory type mem.
    void read(hsize_t r0, hsize_t r1, hid_t mem, void* out, const std::string& where) const {
        if (r1 <= r0 || cols == 0)
            return;
        const int rank = cols >= 0 ? 2 : 1;
        const h5::Id fileSpace = h5::check(H5Dget_space(dset.get()), where, "no dataspace");
        const hsize_t start[2] = {r0, 0};
        const hsize_t count[2] = {r1 - r0, hsize_t(cols > 0 ? cols : 0)};
        h5::check(
            H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
            where, "damaged or truncated record (cannot select rows of " + name + ")");
        const h5::Id memSpace =
            h5::check(H5Screate_simple(rank, count, nullptr), where, "no dataspace");
        h5::check(H5Dread(dset.get(), mem, memSpace.get(), fileSpace.get(), H5P_DEFAULT, out),
                  where, "damaged or truncated record (cannot read " + name + ")");
    }
};

void appendRows(Eigen::VectorXd& out, const Column& c, hsize_t r0, hsize_t r1,
                const std::string& w);
void appendRows(std::vector<int>& out, const Column& c, hsize_t r0, hsize_t r1,
                const std::string& w);
/// Rows [r0, r1) of out from file rows [r0 + offset, r1 + offset).
void appendRows(Eigen::MatrixXd& out, const Column& c, hsize_t r0, hsize_t r1, const std::string& w,
                hsize_t offset = 0);

} // namespace hsmu::recordreader

namespace hsmu {

using recordreader::Column;

struct RecordReader::Impl {
    std::string path;
    h5::Id file;
    bool swmr = false;
    RecordData data;
    Column step, time, ag, u, v, a, def, force, cmd, par, sd, aux, fit, applied, thisStep, pending;
    Column tracking, requested; // schema 2
    Column siteRoundTrip;       // /sites, when the test had experimental elements
    Column alarmTime, alarmStep, alarmSeverity, alarmKind, alarmMessage, alarmCode;
    Column eventStep, eventTime, eventElement, eventValues, eventDecision, eventProposal, noteTime,
        noteStep, noteText;
    Column actCmd, actMeasured, actTicks, actFlags; // /elements/actuator, when present
    bool actuator = false;
    Column channels; // /elements/channels, when the run had multi-DOF elements
    Column dofStep, dofTime; // /dofs/step, /dofs/time: the record chose or decimated its DOFs
    bool dofsChosen = false;
    bool v2 = false;                        // schema 2 datasets present
    std::vector<std::string> decisionCodes; // /updating/events/decision "codes" (if present)

    void open();
    void readMetadata();
    Column column(const char* name, int cols);
    std::vector<Column*> stepColumns();
    /// The rows of /dofs when they are chosen or decimated (their own row count), else none.
    std::vector<Column*> dofColumns();
    int readNewRows();
    void readNewDofRows();
    void readNewAlarms();
    void readNewEvents();
    void readNewNotes();
    std::vector<Column*> logColumns();
    /// SWMR: re-read every dataset's extent from the file (H5Drefresh).
    void refreshDatasets();
    /// Walk every dataset's chunk index (no chunk is read): the file's metadata a read
    /// traverses (a chunk's address is not checked against the size on disk: a record being
    /// written allocates chunks before their bytes reach the file).
    void walkChunkIndexes();
};

} // namespace hsmu
