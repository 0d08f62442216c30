// The record's 2-D chunks (issue 27, docs/recording.md "Chunks"): a wide record's per-step
// matrices are chunked steps x a part of the columns (recordschema::chunkShapeFor), every
// row written reads back exactly (RecordReader, one column through an HDF5 hyperslab as h5py
// reads it, and the CSV export), and a record of the older layout (whole-row chunks) reads
// exactly as its rewrite in the new layout does.
//
// fixtures/record-row-chunks-300.h5 is an older-layout record, written by main before the
// 2-D chunks (program 0.1.0, commit e7fdcca's build):
//   hsmu run shear-building-300 --duration 0.003 --compress 1 --csv none
// (4 rows, 300 DOFs, 300 elements, /dofs/u chunked 250 x 300).

#include "core/record/RecordCsvExport.h"
#include "core/record/RecordReader.h"
#include "core/record/RecordSchema.h"
#include "core/record/RecordWriter.h"

#include <QTemporaryDir>
#include <QtTest>

#include <hdf5.h>

#include <cmath>
#include <fstream>
#include <sstream>

using namespace hsmu;

namespace {

const std::string kFixture =
    std::string(HSMU_SOURCE_DIR) + "/tests/core/record/fixtures/record-row-chunks-300.h5";

/// The chunk dimensions of `dataset` in the file at `path` ({0, 0} when it cannot say).
std::pair<int, int> chunkOf(const std::string& path, const char* dataset) {
    std::pair<int, int> out{0, 0};
    const hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl);
    if (f >= 0) {
        const hid_t d = H5Dopen2(f, dataset, H5P_DEFAULT);
        const hid_t dcpl = d >= 0 ? H5Dget_create_plist(d) : H5I_INVALID_HID;
        hsize_t dims[2] = {0, 0};
        if (dcpl >= 0 && H5Pget_chunk(dcpl, 2, dims) == 2)
            out = {int(dims[0]), int(dims[1])};
        if (dcpl >= 0)
            H5Pclose(dcpl);
        if (d >= 0)
            H5Dclose(d);
        H5Fclose(f);
    }
    H5Pclose(fapl);
    return out;
}

/// Column `col` of the matrix `dataset`, read alone through a hyperslab (h5py's d[:, col]).
std::vector<double> columnOf(const std::string& path, const char* dataset, int col, int rows) {
    std::vector<double> out(std::size_t(rows), std::nan(""));
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(f, dataset, H5P_DEFAULT);
    const hid_t space = H5Dget_space(d);
    const hsize_t start[2] = {0, hsize_t(col)}, count[2] = {hsize_t(rows), 1};
    H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
    const hsize_t len = hsize_t(rows);
    const hid_t mem = H5Screate_simple(1, &len, nullptr);
    if (H5Dread(d, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, out.data()) < 0)
        out.clear();
    H5Sclose(mem);
    H5Sclose(space);
    H5Dclose(d);
    H5Fclose(f);
    return out;
}

/// Equal, NaN equal to NaN (element matrices hold NaN for a numerical element's command).
bool sameMatrix(const Eigen::MatrixXd& x, const Eigen::MatrixXd& y) {
    if (x.rows() != y.rows() || x.cols() != y.cols())
        return false;
    for (Eigen::Index i = 0; i < x.rows(); ++i)
        for (Eigen::Index j = 0; j < x.cols(); ++j)
            if (!(x(i, j) == y(i, j) || (std::isnan(x(i, j)) && std::isnan(y(i, j)))))
                return false;
    return true;
}

/// Row i of a record as the StepRecord that wrote it (DOFs and elements; actuator channels
/// as a numerical element reports them: none).
StepRecord rowOf(const RecordData& d, int i) {
    StepRecord r;
    r.step = d.steps[std::size_t(i)];
    r.time = d.time[i];
    r.groundAcceleration = d.groundAcceleration[i];
    r.u = d.u.row(i).transpose();
    r.v = d.v.row(i).transpose();
    r.a = d.a.row(i).transpose();
    r.elements.resize(std::size_t(d.deformation.cols()));
    for (std::size_t j = 0; j < r.elements.size(); ++j) {
        r.elements[j].deformation = d.deformation(i, Eigen::Index(j));
        r.elements[j].force = d.force(i, Eigen::Index(j));
        r.elements[j].commanded = d.commanded(i, Eigen::Index(j));
    }
    return r;
}

RecordStart startOf(const RecordData& d) {
    RecordStart s;
    s.configuration = d.meta.configuration;
    s.configName = d.meta.configName;
    s.dt = d.meta.dt;
    return s;
}

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Row k, column j: distinct for every (k, j).
double value(int k, int j, int which) {
    return std::sin(0.01 * k + 1e-3 * j + which) + 1e-6 * k;
}

} // namespace

class TestRecordChunks : public QObject {
    Q_OBJECT

private slots:
    // 300 DOFs and elements, 1,201 rows (two whole 500-row batches and a partial one): the
    // matrices are chunked 250 x 100 (three column parts); every value reads back exactly
    // through RecordReader and through a one-column hyperslab.
    void wideRecordsHaveTwoDimensionalChunks() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("wide.h5").toStdString();
        const int n = 300, rows = 1201;
        RunLayout layout;
        for (int j = 0; j < n; ++j) {
            layout.dofNames.push_back("S" + std::to_string(j + 1));
            layout.elements.push_back(
                {"storey " + std::to_string(j + 1), "lateralSpring", false, true, {"m", "kN"}});
        }
        {
            RecordStart start;
            start.dt = 0.001;
            RecordWriter writer(path, layout, start);
            for (int k = 0; k < rows; ++k) {
                StepRecord r;
                r.step = k;
                r.time = 0.001 * k;
                r.u.resize(n);
                r.v.resize(n);
                r.a.resize(n);
                r.elements.resize(std::size_t(n));
                for (int j = 0; j < n; ++j) {
                    r.u[j] = value(k, j, 0);
                    r.v[j] = value(k, j, 1);
                    r.a[j] = value(k, j, 2);
                    r.elements[std::size_t(j)].deformation = value(k, j, 3);
                    r.elements[std::size_t(j)].force = value(k, j, 4);
                }
                writer.onStep(r);
            }
            QVERIFY2(writer.finish(), writer.error().c_str());
        }
        QCOMPARE(RecordWriter::batchRowsFor(n, n), 500); // two chunks' rows
        const recordschema::ChunkShape shape = recordschema::chunkShapeFor(n, 8);
        QCOMPARE(shape.rows, 250);
        QCOMPARE(shape.cols, 100);
        for (const char* d : {"/dofs/u", "/dofs/v", "/dofs/a", "/elements/deformation",
                              "/elements/force", "/elements/commanded",
                              "/elements/actuator/commanded", "/elements/actuator/flags"})
            QCOMPARE(chunkOf(path, d), std::make_pair(250, 100));

        const RecordReader reader(path);
        const RecordData& d = reader.data();
        QCOMPARE(d.rows(), rows);
        for (int k = 0; k < rows; ++k) {
            QCOMPARE(d.steps[std::size_t(k)], k);
            for (int j = 0; j < n; ++j) {
                QCOMPARE(d.u(k, j), value(k, j, 0));
                QCOMPARE(d.v(k, j), value(k, j, 1));
                QCOMPARE(d.a(k, j), value(k, j, 2));
                QCOMPARE(d.deformation(k, j), value(k, j, 3));
                QCOMPARE(d.force(k, j), value(k, j, 4));
                QVERIFY(std::isnan(d.commanded(k, j)));
            }
        }
        // One DOF's whole history alone, in each column part.
        for (int col : {0, 99, 100, 199, 200, 299}) {
            const std::vector<double> c = columnOf(path, "/dofs/u", col, rows);
            QCOMPARE(int(c.size()), rows);
            for (int k = 0; k < rows; ++k)
                QCOMPARE(c[std::size_t(k)], value(k, col, 0));
        }
    }

    // A record of the older layout (whole-row chunks, deflated) reads exactly as its
    // rewrite in the new 2-D layout: the same data through RecordReader and the same CSV
    // files through the export.
    void olderRowChunkedRecordsReadAsTheNewLayout() {
        QVERIFY2(QFileInfo::exists(QString::fromStdString(kFixture)), kFixture.c_str());
        QCOMPARE(chunkOf(kFixture, "/dofs/u"), std::make_pair(250, 300)); // the old layout
        const RecordReader old(kFixture);
        const RecordData& o = old.data();
        QCOMPARE(o.rows(), 4);
        QCOMPARE(int(o.layout.dofNames.size()), 300);
        QCOMPARE(o.meta.schemaVersion, 2);
        // An independent look at the old file: row k at time k dt, row 0 at rest, the
        // building moving by step 3, and one column read alone equal to the whole read.
        for (int k = 0; k < 4; ++k)
            QCOMPARE(o.time[k], k * o.meta.dt);
        QCOMPARE(o.u.row(0).cwiseAbs().maxCoeff(), 0.0);
        QVERIFY(o.u.row(3).cwiseAbs().maxCoeff() > 0.0);
        const std::vector<double> column = columnOf(kFixture, "/dofs/u", 0, 4);
        QCOMPARE(int(column.size()), 4);
        for (int k = 0; k < 4; ++k)
            QCOMPARE(column[std::size_t(k)], o.u(k, 0));

        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("rewritten.h5").toStdString();
        {
            RecordWriter writer(path, o.layout, startOf(o));
            for (int i = 0; i < o.rows(); ++i)
                writer.onStep(rowOf(o, i));
            QVERIFY2(writer.finish(), writer.error().c_str());
        }
        QCOMPARE(chunkOf(path, "/dofs/u"), std::make_pair(250, 100)); // the new layout
        const RecordReader fresh(path);
        const RecordData& n = fresh.data();
        QCOMPARE(n.steps, o.steps);
        QVERIFY(n.time == o.time);
        QVERIFY(n.groundAcceleration == o.groundAcceleration);
        QCOMPARE(n.layout.dofNames, o.layout.dofNames);
        for (const auto& [x, y] : {std::pair{&n.u, &o.u}, {&n.v, &o.v}, {&n.a, &o.a},
                                   {&n.deformation, &o.deformation}, {&n.force, &o.force},
                                   {&n.commanded, &o.commanded},
                                   {&n.actuatorCommanded, &o.actuatorCommanded},
                                   {&n.actuatorMeasured, &o.actuatorMeasured},
                                   {&n.heldTicks, &o.heldTicks},
                                   {&n.actuatorFlags, &o.actuatorFlags}})
            QVERIFY(sameMatrix(*x, *y));

        const std::string oldCsv = dir.filePath("old").toStdString();
        const std::string newCsv = dir.filePath("new").toStdString();
        QVERIFY(QDir().mkpath(QString::fromStdString(oldCsv)));
        QVERIFY(QDir().mkpath(QString::fromStdString(newCsv)));
        exportRecordCsv(o, oldCsv);
        exportRecordCsv(n, newCsv);
        for (const char* file : {"/steps.csv", "/dofs.csv", "/elements.csv", "/actuators.csv"}) {
            const std::string a = fileText(oldCsv + file), b = fileText(newCsv + file);
            QVERIFY2(!a.empty() || std::string(file) == "/actuators.csv", file);
            QVERIFY2(a == b, file);
        }
    }
};

QTEST_GUILESS_MAIN(TestRecordChunks)
#include "TestRecordChunks.moc"
