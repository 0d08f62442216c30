#pragma once
// RecordSchema: names shared by RecordWriter and RecordReader (docs/recording.md is the
// reference for every group, dataset, shape, unit and attribute).

namespace hsmu::recordschema {

/// Root attribute "schema_version"; a reader refuses files with a larger value.
/// 2 added /updating/tracking, /updating/update_requested, /updating/events and /notes.
inline constexpr int kVersion = 2;
/// Rows per HDF5 chunk of every per-step dataset (at most: see kChunkBytes). Equal to
/// RecordWriter::kMaxBufferedRows, the rows of one batch the writer hands its thread: a batch
/// fills whole chunks, so each chunk is written and checksummed once, not once per flush
/// that touched it (issue 27: 1,024-row chunks were written two or three times each).
inline constexpr int kChunkRows = 500;
/// Largest chunk of a per-step matrix [bytes]: a chunk holds whole rows (at least one), at
/// most kChunkBytes, so that it fits HDF5's default 1 MiB chunk cache and an append never
/// reads a chunk back.
inline constexpr int kChunkBytes = 1000 * 1024;
/// Rows per chunk of a per-step dataset whose rows have `cols` values of `bytes` each: the
/// largest divisor of kChunkRows that keeps the chunk within kChunkBytes (1,000 DOFs: 125
/// rows; 10,000 DOFs: 10 rows), so that batches of a multiple of it fill whole chunks.
constexpr int chunkRowsFor(int cols, int bytes)
{
    const long row = long(cols > 0 ? cols : 1) * long(bytes > 0 ? bytes : 1);
    for (int rows = kChunkRows; rows > 1; --rows)
        if (kChunkRows % rows == 0 && rows * row <= kChunkBytes)
            return rows;
    return 1;
}
static_assert(chunkRowsFor(1, 8) == 500 && chunkRowsFor(1000, 8) == 125 &&
              chunkRowsFor(10000, 8) == 10 && chunkRowsFor(200000, 8) == 1);
/// Rows per chunk of the alarm datasets (few rows, long strings).
inline constexpr int kAlarmChunkRows = 32;
/// Fixed string lengths (bytes, null-padded UTF-8) of the alarm datasets; longer texts are cut.
inline constexpr int kSeverityChars = 16;
inline constexpr int kKindChars = 32;
inline constexpr int kMessageChars = 512;
/// Fixed string length of /notes/text.
inline constexpr int kNoteChars = 1024;
/// Columns of /updating/tracking.
inline constexpr int kTrackingColumns = 3;

} // namespace hsmu::recordschema
