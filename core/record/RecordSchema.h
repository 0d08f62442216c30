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
/// Largest chunk of a per-step matrix [bytes]: it fits HDF5's default 1 MiB chunk cache,
/// and reading one column (one DOF's whole history) reads at most kChunkBytes per chunk row
/// band.
inline constexpr int kChunkBytes = 1000 * 1024;
/// Rows per chunk of a per-step dataset whose rows have `cols` values of `bytes` each when a
/// chunk holds whole rows: the largest divisor of kChunkRows that keeps the chunk within
/// kChunkBytes (1,000 DOFs: 125 rows; 10,000 DOFs: 10 rows). Records written before issue
/// 27's 2-D chunks have this shape (rows x all columns); the writer still uses it for the
/// one-dimensional datasets.
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

/// Shape of one chunk of a per-step matrix: `rows` steps x `cols` columns.
struct ChunkShape {
    int rows = 1;
    int cols = 1;
};
/// The 2-D chunk (issue 27, docs/recording.md "Chunks") of a per-step matrix of `cols`
/// values of `bytes` each whose rows are appended `batchRows` at a time: rows = the larger
/// of batchRows (at most kChunkRows) and chunkRowsFor(cols, bytes), so that every full batch
/// fills whole chunks (each written and checksummed once) and a narrow matrix keeps
/// kChunkRows-row chunks; the columns are cut into the fewest equal parts that keep a chunk
/// within kChunkBytes. Reading one column of N rows then reads N x cols_chunk values instead of
/// N x cols: 10,000 DOFs in batches of 50 rows: chunks of 50 x 2,500 (4x less than whole
/// 10-row chunks), 1,000 DOFs in batches of 500: 500 x 250 (4x less).
constexpr ChunkShape chunkShapeFor(int cols, int bytes, int batchRows)
{
    const long width = cols > 0 ? cols : 1, size = bytes > 0 ? bytes : 1;
    const int batch = batchRows < 1 ? 1 : batchRows > kChunkRows ? kChunkRows : batchRows;
    const int whole = chunkRowsFor(int(width), int(size));
    const long rows = batch > whole ? batch : whole;
    long fit = kChunkBytes / (rows * size); // columns that fit one chunk
    fit = fit < 1 ? 1 : fit;
    const long parts = (width + fit - 1) / fit;
    return {int(rows), int((width + parts - 1) / parts)};
}
static_assert(chunkShapeFor(10000, 8, 50).rows == 50 && chunkShapeFor(10000, 8, 50).cols == 2500);
static_assert(chunkShapeFor(1000, 8, 500).rows == 500 && chunkShapeFor(1000, 8, 500).cols == 250);
static_assert(chunkShapeFor(1, 8, 500).rows == 500 && chunkShapeFor(1, 8, 500).cols == 1);
static_assert(chunkShapeFor(7, 8, 10).rows == 500 && chunkShapeFor(7, 8, 10).cols == 7);
static_assert(chunkShapeFor(10000, 8, 10).rows == 10 && chunkShapeFor(10000, 8, 10).cols == 10000);
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
