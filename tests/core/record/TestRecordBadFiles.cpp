// RecordReader on files that are not good records: each gives a RecordError whose message
// names the file and the reason, never a crash. Foreign and newer-schema HDF5 files are made
// with the HDF5 C API directly (this test links HDF5 for that alone).

#include "RecordFixture.h"

#include "core/record/RecordError.h"
#include "core/record/RecordReader.h"
#include "core/record/RecordSchema.h"

#include <hdf5.h>

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace hsmu;
using namespace hsmu::testsupport;

namespace {

/// The RecordError message of opening path ("" if it opened).
std::string openError(const std::string& path) {
    try {
        RecordReader reader(path);
    } catch (const RecordError& e) {
        return e.what();
    }
    return {};
}

void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

std::string recordOf(const QTemporaryDir& dir, double duration) {
    const std::string path = dir.filePath("good.h5").toStdString();
    const TestConfig cfg = condition3(duration);
    auto test = buildHybridTest(cfg);
    RecordWriter writer(path, RunLayout::of(*test), recordStart(cfg));
    test->addObserver(&writer);
    test->prepare();
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    writer.finish();
    return path;
}

} // namespace

class TestRecordBadFiles : public QObject {
    Q_OBJECT
private slots:
    void missingFile();
    void emptyFile();
    void textFile();
    void truncatedRecord();
    void foreignHdf5File();
    void newerSchemaVersion();
};

void TestRecordBadFiles::missingFile() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("absent.h5").toStdString();
    QCOMPARE(openError(path), path + ": cannot be opened (no such file)");
}

void TestRecordBadFiles::emptyFile() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("empty.h5").toStdString();
    writeFile(path, "");
    QCOMPARE(openError(path), path + ": not an HSMU record (not an HDF5 file)");
}

void TestRecordBadFiles::textFile() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("notes.h5").toStdString();
    writeFile(path, "time,force\n0,1\n0.01,2\n");
    QCOMPARE(openError(path), path + ": not an HSMU record (not an HDF5 file)");
}

void TestRecordBadFiles::truncatedRecord() {
    QTemporaryDir dir;
    const std::string good = recordOf(dir, 2.0);
    QVERIFY(openError(good).empty());
    const auto size = std::filesystem::file_size(good);
    std::ifstream in(good, std::ios::binary);
    std::string bytes(size, '\0');
    in.read(bytes.data(), std::streamsize(size));
    for (const double fraction : {0.9, 0.5, 0.1}) {
        const std::string path = dir.filePath("cut.h5").toStdString();
        writeFile(path, bytes.substr(0, std::size_t(double(size) * fraction)));
        const std::string error = openError(path);
        QVERIFY2(error.rfind(path + ": damaged or truncated record", 0) == 0, error.c_str());
    }
}

void TestRecordBadFiles::foreignHdf5File() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("foreign.h5").toStdString();
    const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    QVERIFY(f >= 0);
    const hid_t g = H5Gcreate2(f, "measurements", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    H5Gclose(g);
    H5Fclose(f);
    QCOMPARE(openError(path), path + ": not an HSMU record (no schema_version attribute)");
}

void TestRecordBadFiles::newerSchemaVersion() {
    QTemporaryDir dir;
    const std::string path = recordOf(dir, 0.5);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    QVERIFY(f >= 0);
    const hid_t a = H5Aopen(f, "schema_version", H5P_DEFAULT);
    const int future = 7;
    QVERIFY(H5Awrite(a, H5T_NATIVE_INT, &future) >= 0);
    H5Aclose(a);
    H5Fclose(f);
    QCOMPARE(openError(path), path + ": schema version 7 is newer than this program's " +
                                  std::to_string(recordschema::kVersion));
}

QTEST_APPLESS_MAIN(TestRecordBadFiles)
#include "TestRecordBadFiles.moc"
