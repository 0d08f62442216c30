#pragma once
// Hdf5Util: private helpers of core/record (never included by a public header): an owning
// handle for HDF5 ids, a scope that silences HDF5's own error printing, the text of the
// current HDF5 error stack, string/number attributes, and extendible per-step datasets.
// Every failing call throws RecordError with a message starting with the file's path.

#include "core/record/RecordError.h"
#include "core/record/RecordSchema.h"

#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

namespace hsmu::h5 {

/// Owns one HDF5 id (file, group, dataset, dataspace, type, attribute, property list).
class Id {
public:
    Id() = default;
    explicit Id(hid_t id) : m_id(id) {}
    ~Id() { reset(); }
    Id(Id&& o) noexcept : m_id(std::exchange(o.m_id, H5I_INVALID_HID)) {}
    Id& operator=(Id&& o) noexcept {
        if (this != &o) {
            reset();
            m_id = std::exchange(o.m_id, H5I_INVALID_HID);
        }
        return *this;
    }
    Id(const Id&) = delete;
    Id& operator=(const Id&) = delete;
    hid_t get() const { return m_id; }
    bool valid() const { return m_id >= 0; }
    void reset();
    /// Gives up ownership (the caller closes the id).
    hid_t release() { return std::exchange(m_id, H5I_INVALID_HID); }

private:
    hid_t m_id = H5I_INVALID_HID;
};

/// While alive, HDF5 prints nothing on errors (this thread's default error stack).
class QuietErrors {
public:
    QuietErrors();
    ~QuietErrors();
    QuietErrors(const QuietErrors&) = delete;
    QuietErrors& operator=(const QuietErrors&) = delete;

private:
    H5E_auto2_t m_func = nullptr;
    void* m_data = nullptr;
};

/// The innermost description on the current error stack ("" when empty).
std::string errorText();
/// Throws RecordError("where: what (HDF5: errorText())") when id < 0, else returns Id(id).
Id check(hid_t id, const std::string& where, const std::string& what);
void check(herr_t status, const std::string& where, const std::string& what);

// Attributes (created on obj; strings are variable-length UTF-8, numbers native).
void writeAttr(hid_t obj, const char* name, const std::string& value, const std::string& where);
void writeAttr(hid_t obj, const char* name, const std::vector<std::string>& values,
               const std::string& where);
void writeAttr(hid_t obj, const char* name, double value, const std::string& where);
void writeAttr(hid_t obj, const char* name, int value, const std::string& where);
void writeAttr(hid_t obj, const char* name, const std::vector<int>& values,
               const std::string& where);
bool hasAttr(hid_t obj, const char* name);
std::string readStringAttr(hid_t obj, const char* name, const std::string& where);
std::vector<std::string> readStringsAttr(hid_t obj, const char* name, const std::string& where);
double readDoubleAttr(hid_t obj, const char* name, const std::string& where);
int readIntAttr(hid_t obj, const char* name, const std::string& where);
std::vector<int> readIntsAttr(hid_t obj, const char* name, const std::string& where);

/// A fixed-length, null-padded UTF-8 string type of `chars` bytes.
Id fixedStringType(int chars);

/// A per-step dataset: rows x cols (cols < 0: one-dimensional [rows]) of `type`, unlimited
/// rows, chunked by recordschema::chunkShapeFor(cols, size) (2-D chunks: rows x a part of
/// the columns), at most chunkRows rows. append() extends it and writes `rows` rows from a
/// row-major buffer in memory type `type`. deflate 1-9: each chunk is byte-shuffled and
/// deflated at that level (HDF5's shuffle and deflate filters, before the checksum); 0 none.
class Extendible {
public:
    Extendible() = default;
    Extendible(hid_t parent, const char* name, hid_t type, int cols, const std::string& where,
               int chunkRows = recordschema::kChunkRows, int deflate = 0);
    void append(const void* rowMajor, hsize_t rows);
    hid_t id() const { return m_dset.get(); }
    hsize_t rows() const { return m_rows; }

private:
    Id m_dset;
    hid_t m_type = H5I_INVALID_HID; // not owned
    int m_cols = 0;
    hsize_t m_rows = 0;
    std::string m_where;
};

} // namespace hsmu::h5
