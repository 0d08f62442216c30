// Tests of recording off the stepping thread (issue 27): RecordThread runs its job on a thread
// of its own, one job at a time, and a start() waits for the running job (back-pressure, no
// job is lost); RecordWriter::onStep() allocates nothing on the stepping thread, flushes
// included, and every row it was given reaches the file in order with its values.

#include "core/record/RecordReader.h"
#include "core/record/RecordThread.h"
#include "core/record/RecordWriter.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <new>
#include <thread>

// Allocations made by each thread (the record thread allocates in HDF5; the stepping thread
// must not).
namespace {
thread_local long t_allocations = 0;
}

void* operator new(std::size_t size) {
    ++t_allocations;
    if (void* p = std::malloc(size == 0 ? 1 : size))
        return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

using namespace hsmu;

namespace {

RunLayout layout(int dofs) {
    RunLayout l;
    for (int i = 0; i < dofs; ++i)
        l.dofNames.push_back("S" + std::to_string(i + 1));
    for (int i = 0; i < dofs; ++i)
        l.elements.push_back({"storey " + std::to_string(i + 1), "truss", i == 0, i == 0,
                              ElementUnits{}});
    return l;
}

// Row k: every value a distinct function of k and the column.
void fillRow(StepRecord& r, int k) {
    r.step = k;
    r.time = 0.001 * k;
    r.groundAcceleration = -k;
    for (Eigen::Index i = 0; i < r.u.size(); ++i) {
        r.u[i] = k + 1e-3 * double(i);
        r.v[i] = -k - 1e-3 * double(i);
        r.a[i] = 2.0 * k + double(i);
    }
    for (std::size_t i = 0; i < r.elements.size(); ++i) {
        r.elements[i].deformation = k * 1e-4 + double(i);
        r.elements[i].force = k * 0.5 - double(i);
    }
}

/// Hands `rows` rows of `dofs` DOFs and elements (fillRow) to writer; returns the
/// allocations the stepping thread made meanwhile, and the last row in *last.
long allocationsWhileStepping(RecordWriter& writer, int dofs, int rows, StepRecord* last) {
    StepRecord& r = *last;
    r.u = r.v = r.a = Eigen::VectorXd::Zero(dofs);
    r.elements.resize(std::size_t(dofs));
    const long before = t_allocations;
    for (int k = 0; k < rows; ++k) {
        fillRow(r, k);
        writer.onStep(r);
    }
    return t_allocations - before;
}

} // namespace

class TestRecordThread : public QObject {
    Q_OBJECT

private slots:
    void jobsRunOnTheirOwnThreadOneAtATime() {
        std::atomic<int> running{0}, overlapped{0}, done{0};
        std::thread::id jobThread;
        {
            RecordThread thread([&] {
                if (running.fetch_add(1) != 0)
                    ++overlapped;
                jobThread = std::this_thread::get_id();
                ++done;
                running.fetch_sub(1);
            });
            for (int i = 0; i < 1000; ++i)
                thread.start(); // each waits for the previous job: none is dropped
            thread.wait();
            QCOMPARE(done.load(), 1000);
            thread.start(); // the destructor waits for this one
        }
        QCOMPARE(done.load(), 1001);
        QCOMPARE(overlapped.load(), 0);
        QVERIFY(jobThread != std::this_thread::get_id());
    }

    // A batch fills whole chunks of the widest per-step matrix (each chunk written once) and
    // stays within both memory bounds.
    void batchesFillWholeChunks() {
        QCOMPARE(RecordWriter::batchRowsFor(1, 1), 500);       // the strong SDOF
        QCOMPARE(RecordWriter::batchRowsFor(1000, 1000), 125); // 6,000 values a row
        QCOMPARE(RecordWriter::batchRowsFor(10000, 10000), 10);
        for (std::size_t dofs : {0, 1, 7, 60, 199, 300, 999, 4096, 25000, 100000, 300000})
            for (std::size_t elems : {std::size_t(0), std::size_t(1), dofs / 3, dofs}) {
                const int rows = RecordWriter::batchRowsFor(dofs, elems);
                const int chunk = recordschema::chunkRowsFor(int(std::max(dofs, elems)), 8);
                const long values = long(rows) * long(3 * (dofs + elems));
                QVERIFY(rows >= 1 && rows <= RecordWriter::kMaxBufferedRows);
                QVERIFY(rows == 1 || values <= RecordWriter::kMaxBufferedValues);
                QVERIFY2(rows % chunk == 0 || rows < chunk,
                         qPrintable(QString("%1 DOFs, %2 elements: %3 rows, chunks of %4")
                                        .arg(dofs).arg(elems).arg(rows).arg(chunk)));
                QCOMPARE(recordschema::kChunkRows % chunk, 0);
            }
    }

    void steppingThreadAllocatesNothingPerRow() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("rows.h5").toStdString();
        const int dofs = 300, rows = 3000; // 6 flushes of 500 rows (kMaxBufferedRows)
        RecordWriter writer(path, layout(dofs), RecordStart{"{}", "rows", {}, 0.001});
        StepRecord r;
        const long allocations = allocationsWhileStepping(writer, dofs, rows, &r);
        QVERIFY2(allocations == 0, qPrintable(QString::number(allocations)));
        QVERIFY(writer.rowsFlushed() >= 2000); // flushes were handed over meanwhile
        QVERIFY2(writer.finish(), writer.error().c_str());
        QCOMPARE(writer.rowsFlushed(), rows);

        const RecordReader reader(path);
        const RecordData& d = reader.data();
        QCOMPARE(d.rows(), rows);
        StepRecord expected = r;
        for (int k = 0; k < rows; ++k) {
            fillRow(expected, k);
            QCOMPARE(d.steps[std::size_t(k)], k);
            QCOMPARE(d.time[k], expected.time);
            QVERIFY(d.u.row(k).transpose() == expected.u);
            QVERIFY(d.a.row(k).transpose() == expected.a);
            QCOMPARE(d.force(k, dofs - 1), expected.elements.back().force);
        }
    }

    // Chosen and decimated DOFs (issue 27): the stepping thread still allocates nothing, and
    // the kept values are those given.
    void chosenDofsAllocateNothingPerRow() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("chosen.h5").toStdString();
        const int dofs = 300, rows = 3000, every = 7;
        RecordStart start{"{}", "rows", {}, 0.001};
        start.dofRecording = DofRecording{{0, 17, 299}, every};
        RecordWriter writer(path, layout(dofs), start);
        StepRecord r;
        const long allocations = allocationsWhileStepping(writer, dofs, rows, &r);
        QVERIFY2(allocations == 0, qPrintable(QString::number(allocations)));
        QVERIFY2(writer.finish(), writer.error().c_str());
        const RecordReader reader(path);
        const RecordData& d = reader.data();
        QCOMPARE(d.rows(), rows);
        QCOMPARE(d.dofRows(), (rows - 1) / every + 1);
        StepRecord expected = r;
        for (int k = 0; k < d.dofRows(); ++k) {
            fillRow(expected, every * k);
            QCOMPARE(d.dofStep(k), every * k);
            QCOMPARE(d.dofTime(k), expected.time);
            for (const int j : {0, 1, 2})
                QCOMPARE(d.v(k, j), expected.v[d.dofIndex(j)]);
        }
    }
};

QTEST_APPLESS_MAIN(TestRecordThread)
#include "TestRecordThread.moc"
