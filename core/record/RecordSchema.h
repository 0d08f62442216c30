#pragma once
// RecordSchema: names shared by RecordWriter and RecordReader (docs/recording.md is the
// reference for every group, dataset, shape, unit and attribute).

namespace hsmu::recordschema {

/// Root attribute "schema_version"; a reader refuses files with a larger value.
/// 2 added /updating/tracking, /updating/update_requested, /updating/events and /notes.
inline constexpr int kVersion = 2;
/// Rows per HDF5 chunk of every one-dimensional per-step dataset, and the most rows of a
/// matrix's chunk. Equal to RecordWriter::kMaxBufferedRows, the most rows of one batch the
/// writer hands its thread: a batch fills whole chunks, so each chunk is written and
/// checksummed once, not once per flush that touched it (issue 27: 1,024-row chunks were
/// written two or three times each).
inline constexpr int kChunkRows = 500;
/// Largest chunk of whole rows of a per-step matrix [bytes]: a chunk holds whole rows (at
/// least one), at most kChunkBytes, so that it fits HDF5's default 1 MiB chunk cache and an
/// append never reads a chunk back; chunkShapeFor then cuts its columns.
inline constexpr int kChunkBytes = 1000 * 1024;
/// Rows per chunk of a per-step dataset whose rows have `cols` values of `bytes` each when a
/// chunk holds whole rows: the largest divisor of kChunkRows that keeps the chunk within
/// kChunkBytes (1,000 DOFs: 125 rows; 10,000 DOFs: 10 rows), so that batches of a multiple of
/// it fill whole chunks. Records written before issue 27's 2-D chunks have chunks of these
/// rows x all columns.
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

/// Target size of a per-step matrix's chunk when its rows are cut into column parts [bytes].
inline constexpr int kColumnChunkBytes = 256 * 1024;
/// Shape of one chunk of a per-step matrix: `rows` steps x `cols` columns.
struct ChunkShape {
    int rows = 1;
    int cols = 1;
};
/// The 2-D chunk (issue 27, docs/recording.md "Chunks") of a per-step matrix of `cols`
/// values of `bytes` each: chunkRowsFor's rows (so that the writer's batches, a whole number
/// of them, still fill whole chunks and memory stays where it was), the columns cut into
/// the fewest equal parts that keep a chunk within kColumnChunkBytes. Reading one column
/// (one DOF's whole history) then reads cols_chunk values a row instead of cols: 1,000 DOFs
/// in chunks of 125 x 250, 10,000 DOFs in chunks of 10 x 2,500 (4x less in both).
constexpr ChunkShape chunkShapeFor(int cols, int bytes)
{
    const long width = cols > 0 ? cols : 1, size = bytes > 0 ? bytes : 1;
    const int rows = chunkRowsFor(int(width), int(size));
    const long band = rows * width * size; // one chunk of whole rows [bytes]
    const long parts = (band + kColumnChunkBytes - 1) / kColumnChunkBytes;
    return {rows, int((width + parts - 1) / parts)};
}
static_assert(chunkShapeFor(10000, 8).rows == 10 && chunkShapeFor(10000, 8).cols == 2500);
static_assert(chunkShapeFor(1000, 8).rows == 125 && chunkShapeFor(1000, 8).cols == 250);
static_assert(chunkShapeFor(300, 8).rows == 250 && chunkShapeFor(300, 8).cols == 100);
static_assert(chunkShapeFor(1, 8).rows == 500 && chunkShapeFor(1, 8).cols == 1);
static_assert(chunkShapeFor(7, 8).rows == 500 && chunkShapeFor(7, 8).cols == 7);
static_assert(chunkShapeFor(200000, 8).rows == 1 && chunkShapeFor(200000, 8).cols == 28572);

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
