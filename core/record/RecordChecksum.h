#pragma once
// RecordChecksum: a 64-bit FNV-1a checksum of a record's metadata (root attributes and the
// layout's names, types and units), stored by RecordWriter as the root attribute
// metadata_checksum (16 hex digits) and checked by RecordReader. HDF5 checksums its own
// structures and, with the Fletcher32 filter, every data chunk; variable-length strings (the
// attributes' text lives in the global heap) carry none: this closes that gap, so a flipped
// byte in the configuration text is reported, not read as a different configuration.

#include "core/output/RunLayout.h"
#include "core/record/RecordData.h"

#include <string>

namespace hsmu {

/// 16 lower-case hex digits. schemaVersion is not part of it (it selects the reader).
std::string recordMetadataChecksum(const RecordMetadata& meta, const RunLayout& layout);

} // namespace hsmu
