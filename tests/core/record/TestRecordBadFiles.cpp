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

#include <chrono>
#include <cstring>
#include <filesystem>
#include <random>

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
    void flippedDataByteIsReported();
    void corruptedCopiesFailOrReadTheSame();
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

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// "" if a and b have the same rows, steps, times, displacements, forces, alarms and
/// metadata; else what differs.
std::string difference(const RecordData& a, const RecordData& b) {
    if (a.rows() != b.rows())
        return "rows";
    if (a.steps != b.steps || a.time != b.time)
        return "steps or time";
    if (a.u != b.u || a.force != b.force || a.deformation != b.deformation)
        return "u, force or deformation";
    if (a.alarms.size() != b.alarms.size())
        return "alarms";
    for (std::size_t i = 0; i < a.alarms.size(); ++i)
        if (a.alarms[i].message != b.alarms[i].message)
            return "alarm text '" + a.alarms[i].message + "'";
    if (a.meta.configuration != b.meta.configuration || a.meta.configName != b.meta.configName ||
        a.meta.program != b.meta.program || a.meta.startTime != b.meta.startTime)
        return "metadata";
    if (a.layout.dofNames != b.layout.dofNames)
        return "layout";
    return {};
}

} // namespace

void TestRecordBadFiles::flippedDataByteIsReported() {
    // The time column holds k * dt; flip one byte of t = 1.5 s: the chunk's Fletcher32
    // checksum no longer matches, so the read fails instead of replaying a wrong time.
    QTemporaryDir dir;
    const std::string good = recordOf(dir, 2.0);
    std::string bytes = readBytes(good);
    const double t = 150 * 0.01;
    char pattern[8];
    std::memcpy(pattern, &t, 8);
    const auto at = bytes.find(std::string(pattern, 8));
    QVERIFY(at != std::string::npos);
    bytes[at + 3] = char(bytes[at + 3] ^ 0x10);
    const std::string path = dir.filePath("flipped.h5").toStdString();
    writeFile(path, bytes);
    const std::string error = openError(path);
    QVERIFY2(error.rfind(path + ": damaged or truncated record (cannot read", 0) == 0,
             error.c_str());
}

void TestRecordBadFiles::corruptedCopiesFailOrReadTheSame() {
    // Fuzz: truncated, byte-flipped and zeroed (64-byte block) copies of a real record at
    // seeded random offsets. Each either fails with a RecordError naming the file (within
    // the reader's deadline: a hang inside HDF5 is cut at kRecordOpenDeadline) or, when the
    // damage hit bytes the record does not use, reads exactly the original data. Never a
    // crash, a hang or silently different data.
    QTemporaryDir dir;
    const std::string good = recordOf(dir, 1.0);
    const RecordReader original(good);
    const std::string bytes = readBytes(good);
    std::mt19937_64 rng(1414);
    std::uniform_int_distribution<std::size_t> offset(0, bytes.size() - 1);
    const char* classes[] = {"truncated", "flipped", "zeroed"};
    int failed[3] = {0, 0, 0}, same[3] = {0, 0, 0};
    double slowest[3] = {0, 0, 0};
    const std::string path = dir.filePath("fuzz.h5").toStdString();
    for (int k = 0; k < 36; ++k) {
        const int c = k % 3;
        std::string b = bytes;
        const std::size_t at = offset(rng);
        if (c == 0)
            b.resize(at);
        else if (c == 1)
            b[at] = char(b[at] ^ (1 << (k % 8)));
        else
            std::memset(b.data() + at, 0, std::min<std::size_t>(64, b.size() - at));
        writeFile(path, b);
        const auto start = std::chrono::steady_clock::now();
        std::string error;
        std::string differs;
        try {
            const RecordReader r(path);
            differs = difference(r.data(), original.data());
        } catch (const RecordError& e) {
            error = e.what();
        }
        const double took =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        slowest[c] = std::max(slowest[c], took);
        if (error.empty()) {
            QVERIFY2(differs.empty(), qPrintable(QString("%1 at byte %2 read different data: %3")
                                                     .arg(classes[c])
                                                     .arg(at)
                                                     .arg(QString::fromStdString(differs))));
            ++same[c];
        } else {
            QVERIFY2(error.rfind(path + ": ", 0) == 0, error.c_str());
            ++failed[c];
        }
    }
    for (int c = 0; c < 3; ++c)
        qInfo("%s: %d failed with a message, %d unharmed, slowest %.2f s", classes[c],
              failed[c], same[c], slowest[c]);
    QCOMPARE(failed[0], 12); // every truncation is noticed
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
