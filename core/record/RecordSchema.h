#pragma once
// RecordSchema: names shared by RecordWriter and RecordReader (docs/recording.md is the
// reference for every group, dataset, shape, unit and attribute).

namespace hsmu::recordschema {

/// Root attribute "schema_version"; a reader refuses files with a larger value.
/// 2 added /updating/tracking, /updating/update_requested, /updating/events and /notes.
inline constexpr int kVersion = 2;
/// Rows per HDF5 chunk of every per-step dataset (at most: see kChunkBytes).
inline constexpr int kChunkRows = 1024;
/// Largest chunk of a per-step matrix [bytes]: a chunk holds min(kChunkRows,
/// kChunkBytes / row bytes) whole rows (at least one), so that it fits HDF5's default 1 MiB
/// chunk cache and an append never reads a chunk back (10,000 DOFs: 13 rows per chunk).
inline constexpr int kChunkBytes = 1000 * 1024;
/// Rows per chunk of a per-step dataset whose rows have `cols` values of `bytes` each.
constexpr int chunkRowsFor(int cols, int bytes)
{
    const long row = long(cols > 0 ? cols : 1) * long(bytes > 0 ? bytes : 1);
    const long rows = kChunkBytes / row;
    return int(rows < 1 ? 1 : rows > kChunkRows ? kChunkRows : rows);
}
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
