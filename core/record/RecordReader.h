#pragma once
// RecordReader: opens a run record (RecordWriter's HDF5 file, docs/recording.md) read-only and
// returns its metadata and per-step data as RecordData.
//
// The file is opened in SWMR read mode when its format allows, so a record that a running
// test (another process) is still writing can be read; refresh() then picks up the rows
// flushed since. The row count N is the smallest row count over the per-step datasets, so a
// read racing the writer's flush never returns half a row. A second reader of a file that an
// earlier reader in the same process still holds open reads what is on disk when it opens
// (HDF5 shares the open file; the extents are refreshed first), like the first after refresh().
//
// Errors (RecordError, the message starts with the path), never a crash:
//   "FILE: cannot be opened (no such file)"
//   "FILE: not an HSMU record (not an HDF5 file)"      empty, text, or foreign files
//   "FILE: not an HSMU record (no schema_version attribute)"
//   "FILE: schema version N is newer than this program's M"
//   "FILE: damaged or truncated record (...)"          HDF5 cannot open or read it
// Thread rules: one thread per reader.

#include "core/record/RecordData.h"

#include <memory>
#include <string>

namespace hsmu {

class RecordReader {
public:
    /// Opens and reads the whole file. Throws RecordError.
    explicit RecordReader(const std::string& path);
    ~RecordReader();
    RecordReader(const RecordReader&) = delete;
    RecordReader& operator=(const RecordReader&) = delete;

    const RecordData& data() const;
    const std::string& path() const;
    int rows() const { return data().rows(); }
    /// Reads rows and alarms added since the last read (a concurrent SWMR writer); returns
    /// the number of new rows. Throws RecordError if the file became unreadable.
    int refresh();
    /// Whether the file was opened in SWMR read mode.
    bool swmr() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_d;
};

} // namespace hsmu
