// The record's chunk shapes at scale (issue 27, docs/benchmarks.md "The record's 2-D chunks"):
//   bmRecordWideWrite/N     RecordWriter: N DOFs and N elements (a shear building's layout),
//                           1,001 rows (1 s at dt 0.001) written to a temporary file, per row
//   bmRecordReadOneChannel/N  one DOF's whole history (/dofs/u column N/2, 1,001 rows) read
//                           from that record with an HDF5 hyperslab, as h5py's d[:, j] or
//                           MATLAB's h5read(file, '/dofs/u', [j 1], [1 Inf]) read it
//   bmRecordReadWhole/N     RecordReader opening the whole record (hsmu export, hsmu.Record)
// The rows are synthetic (every value distinct and non-zero, so that no chunk is all zeros);
// only the recording and the reading are timed. The file is left in the page cache (a read
// right after a run), so the reads measure HDF5's work (chunk lookups, Fletcher32, copies),
// not the disk.
// Run: build/bin/hsmu_bench --benchmark_filter='RecordWide|RecordRead'

#include "core/output/RunLayout.h"
#include "core/record/RecordReader.h"
#include "core/record/RecordWriter.h"

#include <benchmark/benchmark.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using namespace hsmu;

constexpr int kRows = 1001; // 1 s at dt = 0.001 s, step 0 included

std::string widePath(int n) {
    return (std::filesystem::temp_directory_path() /
            ("hsmu_bench_wide_" + std::to_string(n) + ".h5"))
        .string();
}

RunLayout wideLayout(int n) {
    RunLayout layout;
    for (int i = 0; i < n; ++i) {
        layout.dofNames.push_back("Storey " + std::to_string(i + 1));
        ElementInfo e;
        e.name = "Spring " + std::to_string(i + 1);
        e.type = "lateralSpring";
        e.nonlinear = true;
        e.units = {"m", "kN"};
        layout.elements.push_back(e);
    }
    return layout;
}

/// Eight distinct synthetic rows, cycled (step and time set per row written).
std::vector<StepRecord> wideRows(int n) {
    std::vector<StepRecord> rows(8);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        StepRecord& r = rows[k];
        r.u.resize(n);
        r.v.resize(n);
        r.a.resize(n);
        r.elements.resize(std::size_t(n));
        for (int i = 0; i < n; ++i) {
            const double x = 1e-3 * std::sin(0.37 * double(k + 1) + 1e-3 * double(i + 1));
            r.u[i] = x;
            r.v[i] = 3.0 * x + 1e-9;
            r.a[i] = -7.0 * x - 1e-9;
            r.elements[std::size_t(i)].deformation = x * 0.5;
            r.elements[std::size_t(i)].force = x * 40.0;
        }
    }
    return rows;
}

void writeWide(const std::string& path, int n, const std::vector<StepRecord>& rows) {
    RecordStart start;
    start.configName = "wide";
    start.dt = 0.001;
    RecordWriter writer(path, wideLayout(n), start);
    for (int k = 0; k < kRows; ++k) {
        StepRecord r = rows[std::size_t(k) % rows.size()];
        r.step = k;
        r.time = 0.001 * k;
        writer.onStep(r);
    }
    writer.finish();
}

void bmRecordWideWrite(benchmark::State& state) {
    const int n = int(state.range(0));
    const std::vector<StepRecord> rows = wideRows(n);
    const std::string path = widePath(n);
    for (auto _ : state)
        writeWide(path, n, rows);
    state.SetItemsProcessed(state.iterations() * kRows); // rows
    state.counters["bytes_per_row"] = double(std::filesystem::file_size(path)) / kRows;
    std::filesystem::remove(path);
}
// Process CPU: the record thread writes (RecordThread), the stepping thread only copies rows.
BENCHMARK(bmRecordWideWrite)->Arg(1000)->Arg(10000)->MeasureProcessCPUTime()->Unit(
    benchmark::kMillisecond);

void bmRecordReadOneChannel(benchmark::State& state) {
    const int n = int(state.range(0));
    const std::string path = widePath(n);
    writeWide(path, n, wideRows(n));
    std::vector<double> column(kRows);
    for (auto _ : state) {
        const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        const hid_t d = H5Dopen2(file, "/dofs/u", H5P_DEFAULT);
        const hid_t space = H5Dget_space(d);
        const hsize_t start[2] = {0, hsize_t(n / 2)}, count[2] = {kRows, 1};
        H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr);
        const hsize_t len = kRows;
        const hid_t mem = H5Screate_simple(1, &len, nullptr);
        const herr_t status = H5Dread(d, H5T_NATIVE_DOUBLE, mem, space, H5P_DEFAULT, column.data());
        H5Sclose(mem);
        H5Sclose(space);
        H5Dclose(d);
        H5Fclose(file);
        if (status < 0) {
            state.SkipWithError("cannot read /dofs/u");
            break;
        }
        benchmark::DoNotOptimize(column.data());
    }
    state.counters["checksum"] = column[kRows / 2]; // the same value before and after
    std::filesystem::remove(path);
}
BENCHMARK(bmRecordReadOneChannel)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

void bmRecordReadWhole(benchmark::State& state) {
    const int n = int(state.range(0));
    const std::string path = widePath(n);
    writeWide(path, n, wideRows(n));
    for (auto _ : state) {
        RecordReader reader(path);
        benchmark::DoNotOptimize(reader.rows());
    }
    std::filesystem::remove(path);
}
BENCHMARK(bmRecordReadWhole)->Arg(1000)->Arg(10000)->Unit(benchmark::kMillisecond);

} // namespace
