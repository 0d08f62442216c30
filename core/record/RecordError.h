#pragma once
// RecordError: a run record (HDF5 file) could not be written or read. The message starts with
// the file's path, e.g. "run/record.h5: not an HSMU record (no schema_version attribute)".

#include <stdexcept>
#include <string>

namespace hsmu {

class RecordError : public std::runtime_error {
public:
    explicit RecordError(const std::string& message) : std::runtime_error(message) {}
};

} // namespace hsmu
