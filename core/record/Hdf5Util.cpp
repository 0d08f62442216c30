#include "core/record/Hdf5Util.h"

#include "core/record/RecordSchema.h"

#include <algorithm>
#include <cstdlib>

namespace hsmu::h5 {

void Id::reset() {
    if (m_id < 0)
        return;
    switch (H5Iget_type(m_id)) {
    case H5I_FILE:
        H5Fclose(m_id);
        break;
    case H5I_GROUP:
        H5Gclose(m_id);
        break;
    case H5I_DATASET:
        H5Dclose(m_id);
        break;
    case H5I_DATASPACE:
        H5Sclose(m_id);
        break;
    case H5I_DATATYPE:
        H5Tclose(m_id);
        break;
    case H5I_ATTR:
        H5Aclose(m_id);
        break;
    case H5I_GENPROP_LST:
        H5Pclose(m_id);
        break;
    default:
        break;
    }
    m_id = H5I_INVALID_HID;
}

QuietErrors::QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &m_func, &m_data);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

QuietErrors::~QuietErrors() {
    H5Eset_auto2(H5E_DEFAULT, m_func, m_data);
}

namespace {

herr_t innermost(unsigned n, const H5E_error2_t* err, void* out) {
    if (n == 0 && err && err->desc)
        *static_cast<std::string*>(out) = err->desc;
    return 0;
}

std::string failure(const std::string& where, const std::string& what) {
    const std::string hdf5 = errorText();
    return where + ": " + what + (hdf5.empty() ? "" : " (HDF5: " + hdf5 + ")");
}

} // namespace

std::string errorText() {
    std::string text;
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, innermost, &text);
    return text;
}

Id check(hid_t id, const std::string& where, const std::string& what) {
    if (id < 0)
        throw RecordError(failure(where, what));
    return Id(id);
}

void check(herr_t status, const std::string& where, const std::string& what) {
    if (status < 0)
        throw RecordError(failure(where, what));
}

namespace {

Id vlenString(const std::string& where) {
    Id t = check(H5Tcopy(H5T_C_S1), where, "cannot make a string type");
    check(H5Tset_size(t.get(), H5T_VARIABLE), where, "cannot make a string type");
    check(H5Tset_cset(t.get(), H5T_CSET_UTF8), where, "cannot make a string type");
    return t;
}

Id openAttr(hid_t obj, const char* name, const std::string& where) {
    return check(H5Aopen(obj, name, H5P_DEFAULT), where,
                 std::string("missing attribute \"") + name + "\"");
}

void createAndWrite(hid_t obj, const char* name, hid_t fileType, hid_t memType, hid_t space,
                    const void* data, const std::string& where) {
    if (H5Aexists(obj, name) > 0)
        check(H5Adelete(obj, name), where, std::string("cannot replace attribute ") + name);
    const Id a = check(H5Acreate2(obj, name, fileType, space, H5P_DEFAULT, H5P_DEFAULT), where,
                       std::string("cannot create attribute ") + name);
    check(H5Awrite(a.get(), memType, data), where, std::string("cannot write attribute ") + name);
}

hssize_t attrPoints(hid_t attr) {
    const Id space(H5Aget_space(attr));
    return space.valid() ? H5Sget_simple_extent_npoints(space.get()) : -1;
}

} // namespace

void writeAttr(hid_t obj, const char* name, const std::string& value, const std::string& where) {
    const Id t = vlenString(where);
    const Id space = check(H5Screate(H5S_SCALAR), where, "cannot make a dataspace");
    const char* p = value.c_str();
    createAndWrite(obj, name, t.get(), t.get(), space.get(), &p, where);
}

void writeAttr(hid_t obj, const char* name, const std::vector<std::string>& values,
               const std::string& where) {
    const Id t = vlenString(where);
    const hsize_t n = values.size();
    const Id space = check(H5Screate_simple(1, &n, nullptr), where, "cannot make a dataspace");
    std::vector<const char*> p;
    for (const auto& v : values)
        p.push_back(v.c_str());
    createAndWrite(obj, name, t.get(), t.get(), space.get(), p.data(), where);
}

void writeAttr(hid_t obj, const char* name, double value, const std::string& where) {
    const Id space = check(H5Screate(H5S_SCALAR), where, "cannot make a dataspace");
    createAndWrite(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space.get(), &value, where);
}

void writeAttr(hid_t obj, const char* name, int value, const std::string& where) {
    const Id space = check(H5Screate(H5S_SCALAR), where, "cannot make a dataspace");
    createAndWrite(obj, name, H5T_STD_I32LE, H5T_NATIVE_INT, space.get(), &value, where);
}

void writeAttr(hid_t obj, const char* name, const std::vector<int>& values,
               const std::string& where) {
    const hsize_t n = values.size();
    const Id space = check(H5Screate_simple(1, &n, nullptr), where, "cannot make a dataspace");
    createAndWrite(obj, name, H5T_STD_I32LE, H5T_NATIVE_INT, space.get(), values.data(), where);
}

bool hasAttr(hid_t obj, const char* name) {
    return H5Aexists(obj, name) > 0;
}

std::vector<std::string> readStringsAttr(hid_t obj, const char* name, const std::string& where) {
    const Id a = openAttr(obj, name, where);
    const Id fileType = check(H5Aget_type(a.get()), where, "bad attribute type");
    if (H5Tget_class(fileType.get()) != H5T_STRING)
        throw RecordError(where + ": attribute \"" + name + "\" is not a string");
    const hssize_t n = attrPoints(a.get());
    if (n < 0)
        throw RecordError(where + ": attribute \"" + name + "\" is unreadable");
    std::vector<std::string> out;
    if (H5Tis_variable_str(fileType.get()) > 0) {
        const Id t = vlenString(where);
        std::vector<char*> p(std::size_t(n), nullptr);
        check(H5Aread(a.get(), t.get(), p.data()), where,
              std::string("cannot read attribute ") + name);
        for (char* s : p) {
            out.emplace_back(s ? s : "");
            std::free(s); // vlen strings are allocated by HDF5 with malloc
        }
        return out;
    }
    const std::size_t size = H5Tget_size(fileType.get());
    std::vector<char> buf(size * std::size_t(n) + 1, '\0');
    const Id t = check(H5Tcopy(fileType.get()), where, "bad attribute type");
    check(H5Aread(a.get(), t.get(), buf.data()), where,
          std::string("cannot read attribute ") + name);
    for (hssize_t i = 0; i < n; ++i) {
        const char* s = buf.data() + std::size_t(i) * size;
        std::size_t len = 0;
        while (len < size && s[len] != '\0')
            ++len;
        out.emplace_back(s, len);
    }
    return out;
}

std::string readStringAttr(hid_t obj, const char* name, const std::string& where) {
    const auto v = readStringsAttr(obj, name, where);
    return v.empty() ? std::string() : v.front();
}

std::vector<int> readIntsAttr(hid_t obj, const char* name, const std::string& where) {
    const Id a = openAttr(obj, name, where);
    const hssize_t n = attrPoints(a.get());
    if (n < 0)
        throw RecordError(where + ": attribute \"" + name + "\" is unreadable");
    std::vector<int> out(std::size_t(n), 0);
    check(H5Aread(a.get(), H5T_NATIVE_INT, out.data()), where,
          std::string("attribute \"") + name + "\" is not an integer");
    return out;
}

int readIntAttr(hid_t obj, const char* name, const std::string& where) {
    const auto v = readIntsAttr(obj, name, where);
    if (v.size() != 1)
        throw RecordError(where + ": attribute \"" + name + "\" is not a single integer");
    return v.front();
}

double readDoubleAttr(hid_t obj, const char* name, const std::string& where) {
    const Id a = openAttr(obj, name, where);
    if (attrPoints(a.get()) != 1)
        throw RecordError(where + ": attribute \"" + name + "\" is not a single number");
    double v = 0.0;
    check(H5Aread(a.get(), H5T_NATIVE_DOUBLE, &v), where,
          std::string("attribute \"") + name + "\" is not a number");
    return v;
}

Id fixedStringType(int chars) {
    Id t(H5Tcopy(H5T_C_S1));
    H5Tset_size(t.get(), std::size_t(chars));
    H5Tset_strpad(t.get(), H5T_STR_NULLPAD);
    H5Tset_cset(t.get(), H5T_CSET_UTF8);
    return t;
}

Extendible::Extendible(hid_t parent, const char* name, hid_t type, int cols,
                       const std::string& where, int chunkRows, int deflate)
    : m_type(type), m_cols(cols), m_where(where + ": " + name) {
    const int rank = cols >= 0 ? 2 : 1;
    const hsize_t width = hsize_t(cols > 0 ? cols : 0);
    const hsize_t dims[2] = {0, width};
    // A zero-width matrix still needs a positive chunk, hence an unlimited second dimension.
    const hsize_t maxDims[2] = {H5S_UNLIMITED, cols > 0 ? width : H5S_UNLIMITED};
    // At most chunkRows rows; a matrix's columns cut as chunkShapeFor does (2-D chunks).
    const recordschema::ChunkShape shape =
        recordschema::chunkShapeFor(cols, int(H5Tget_size(type)));
    const int rowsPerChunk = std::min(chunkRows > 0 ? chunkRows : 1, shape.rows);
    const hsize_t chunk[2] = {hsize_t(rowsPerChunk), cols > 0 ? hsize_t(shape.cols) : 1};
    const Id space = check(H5Screate_simple(rank, dims, maxDims), where, "cannot make a dataspace");
    const Id dcpl = check(H5Pcreate(H5P_DATASET_CREATE), where, "cannot make a property list");
    check(H5Pset_chunk(dcpl.get(), rank, chunk), where, "cannot set chunking");
    if (deflate > 0) {
        check(H5Pset_shuffle(dcpl.get()), where, "cannot set the shuffle filter");
        check(H5Pset_deflate(dcpl.get(), unsigned(std::min(deflate, 9))), where,
              "cannot set the deflate filter");
    }
    // Every chunk carries a Fletcher32 checksum: a flipped data byte fails the read
    // (RecordReader: "damaged or truncated record (cannot read ...)"), it is never replayed.
    check(H5Pset_fletcher32(dcpl.get()), where, "cannot set the Fletcher32 checksum");
    m_dset =
        check(H5Dcreate2(parent, name, type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
              where, std::string("cannot create dataset ") + name);
}

void Extendible::append(const void* rowMajor, hsize_t rows) {
    if (rows == 0 || !m_dset.valid())
        return;
    if (m_cols == 0) { // nothing to write, only the row count grows
        const hsize_t newDims[2] = {m_rows + rows, 0};
        check(H5Dset_extent(m_dset.get(), newDims), m_where, "cannot extend");
        m_rows += rows;
        return;
    }
    const int rank = m_cols > 0 ? 2 : 1;
    const hsize_t newDims[2] = {m_rows + rows, hsize_t(m_cols > 0 ? m_cols : 0)};
    check(H5Dset_extent(m_dset.get(), newDims), m_where, "cannot extend");
    const Id fileSpace = check(H5Dget_space(m_dset.get()), m_where, "no dataspace");
    const hsize_t start[2] = {m_rows, 0};
    const hsize_t count[2] = {rows, hsize_t(m_cols > 0 ? m_cols : 0)};
    check(H5Sselect_hyperslab(fileSpace.get(), H5S_SELECT_SET, start, nullptr, count, nullptr),
          m_where, "cannot select rows");
    const Id memSpace = check(H5Screate_simple(rank, count, nullptr), m_where, "no dataspace");
    check(H5Dwrite(m_dset.get(), m_type, memSpace.get(), fileSpace.get(), H5P_DEFAULT, rowMajor),
          m_where, "cannot write");
    m_rows += rows;
}

} // namespace hsmu::h5
