#include "python/PyRun.h"

#include "comms/link/ControlFactory.h"
#include "core/config/ConfigLoader.h"
#include "core/config/ShearBuilding.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/output/RunLayout.h"
#include "core/output/RunStatistics.h"
#include "core/output/RunSummary.h"
#include "core/output/StepCsvWriter.h"
#include "core/session/TestSession.h"
#include "python/PyArrays.h"
#include "python/PyInterrupt.h"
#include "python/PyJson.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace hsmu::python {

namespace {

/// Where the presets are: beside an installed module (PREFIX/lib/python3/dist-packages ->
/// PREFIX/share/hsmu/presets), else the source tree's (a build-tree module).
std::vector<fs::path> presetDirs() {
    std::vector<fs::path> dirs;
    const fs::path module = py::module_::import("hsmu").attr("__file__").cast<std::string>();
    dirs.push_back(module.parent_path() / "../../../share/hsmu/presets");
    dirs.push_back(fs::path(HSMU_SOURCE_PRESETS));
    return dirs;
}

std::vector<std::string> presetNames() {
    std::vector<std::string> names;
    for (const fs::path& dir : presetDirs()) {
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(dir, ec))
            if (entry.path().extension() == ".json")
                names.push_back(entry.path().stem().string());
        if (!names.empty())
            break;
    }
    std::sort(names.begin(), names.end());
    return names;
}

/// The rule of `hsmu run CONFIG` (gui/PresetLibrary.h): an existing file; else a preset name
/// (read with the source name "preset <id>", as the program's embedded copy); else the
/// generated shear-building family; else a path, which fails naming it.
TestConfig loadConfig(py::handle config) {
    if (py::isinstance<py::dict>(config))
        return parseConfig(toJson(config, "config"), "config (dict)");
    const std::string name = py::str(py::module_::import("os").attr("fspath")(config));
    if (fs::is_regular_file(name))
        return loadConfigFile(name);
    if (name.find('/') == std::string::npos) {
        for (const fs::path& dir : presetDirs()) {
            const fs::path file = dir / (name + ".json");
            if (!fs::is_regular_file(file))
                continue;
            std::ifstream in(file);
            nlohmann::json doc;
            try {
                doc = nlohmann::json::parse(in);
            } catch (const nlohmann::json::exception& e) {
                throw ConfigError("preset " + name + ": " + e.what());
            }
            return parseConfig(doc, "preset " + name);
        }
        if (auto spec = parseShearBuildingName(name))
            return parseConfig(shearBuildingConfig(*spec), "preset " + name);
    }
    if (name.find('/') != std::string::npos || name.ends_with(".json"))
        return loadConfigFile(name);
    std::string ids;
    for (const auto& id : presetNames())
        ids += (ids.empty() ? "" : ", ") + id;
    throw ConfigError(name + ": neither a configuration file nor a preset (presets: " + ids +
                      ", and the generated shear-building-<N>[-elastic][-mass-damped])");
}

/// Every committed step's StepCsvWriter values, and the caller's progress every 1 %.
class StepTable final : public StepObserver {
public:
    StepTable(RunLayout layout, int totalSteps, py::handle progress)
        : m_layout(std::move(layout)), m_total(std::max(1, totalSteps)),
          m_progress(progress.is_none() ? py::object()
                                        : py::reinterpret_borrow<py::object>(progress)) {}
    void onStep(const StepRecord& record) override {
        StepCsvWriter::rowValues(m_layout, record, m_row);
        m_values.insert(m_values.end(), m_row.begin(), m_row.end());
        ++m_rows;
        if (m_progress && (record.step >= m_next || record.step == m_total)) {
            m_next = record.step + std::max(1, m_total / 100);
            py::gil_scoped_acquire acquire;
            py::dict p;
            p["step"] = record.step;
            p["total_steps"] = m_total;
            p["time_s"] = record.time;
            m_progress(p);
        }
    }
    py::dict arrays() const {
        py::dict out;
        const auto names = StepCsvWriter::columnNames(m_layout);
        for (std::size_t j = 0; j < names.size(); ++j) {
            RealArray a = newVector(m_rows);
            for (std::size_t i = 0; i < m_rows; ++i)
                a.mutable_data()[i] = m_values[i * names.size() + j];
            out[py::str(names[j])] = a;
        }
        return out;
    }

private:
    RunLayout m_layout;
    int m_total;
    py::object m_progress;
    std::vector<double> m_row, m_values;
    std::size_t m_rows = 0;
    int m_next = 0;
};

const char* statusName(TestSession::Status s) {
    switch (s) {
    case TestSession::Status::Finished:
        return "finished";
    case TestSession::Status::Held:
        return "held";
    case TestSession::Status::Failed:
        return "failed";
    default:
        return "stopped";
    }
}

py::dict run(py::handle config, py::handle groundMotion, py::handle scale, py::handle out,
             py::handle progress) {
    TestConfig cfg = loadConfig(config);
    if (!groundMotion.is_none()) { // as --ground-motion FILE (gui/ConfigOverrides)
        cfg.groundMotion.file =
            fs::absolute(
                py::str(py::module_::import("os").attr("fspath")(groundMotion)).cast<std::string>())
                .string();
        cfg.groundMotion.format = "auto";
        cfg.groundMotion.units.clear();
        cfg.groundMotion.dt = 0.0;
    }
    if (!scale.is_none())
        cfg.groundMotion.scale = scale.cast<double>();
    std::unique_ptr<HybridTest> test =
        buildHybridTest(cfg, comms::makeControlFactory(comms::LinkAddress{}, {}, cfg));
    const RunLayout layout = RunLayout::of(*test);

    std::optional<fs::path> dir;
    if (!out.is_none()) {
        dir = fs::path(py::str(py::module_::import("os").attr("fspath")(out)).cast<std::string>());
        std::error_code ec;
        fs::create_directories(*dir, ec);
        if (!fs::is_directory(*dir))
            throw py::value_error(dir->string() + ": cannot create the output directory");
    }
    std::unique_ptr<StepCsvWriter> csv;
    if (dir && StepCsvWriter::columnCount(layout) <= StepCsvWriter::kMaxColumns)
        csv = std::make_unique<StepCsvWriter>((*dir / "steps.csv").string(), layout);
    SessionOptions options;
    if (dir)
        options.recordPath = (*dir / "record.h5").string();
    options.recordStart = RecordStart{cfg.raw.dump(), cfg.name, {}, cfg.analysis.dt};
    const int total = test->totalSteps();
    TestSession session(std::move(test), options);
    if (!session.openRecord())
        throw py::value_error(session.lastError());
    RunStatistics stats(layout);
    StepTable table(layout, total, progress);
    if (csv)
        session.addObserver(csv.get());
    session.addObserver(&stats);
    session.addObserver(&table);
    if (!session.prepare())
        throw py::value_error("the test cannot start: " + session.lastError());

    TestSession::Status status = TestSession::Status::Failed;
    const auto started = std::chrono::steady_clock::now();
    const bool interrupted =
        runInterruptible([&] { status = session.runToEnd(); },
                         [&] { session.emergencyHold("SIGINT received"); }, false);
    RunInfo info;
    info.configName = cfg.name;
    info.configFile = cfg.sourcePath;
    info.wallTimeS =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    session.removeObserver(&table);
    session.removeObserver(&stats);
    if (csv)
        session.removeObserver(csv.get());
    std::string error;
    if (!session.finish())
        error = session.lastError();
    if (csv && !csv->finish())
        error = csv->path() + ": write failed";
    if (dir)
        writeSummaryJson((*dir / "summary.json").string(), session.test(), stats, info);
    if (!error.empty())
        throw py::value_error(error);

    py::dict result;
    result["status"] = statusName(status);
    result["interrupted"] = interrupted;
    const auto reason = holdReason(session.test());
    result["hold_reason"] = reason ? py::object(py::str(*reason)) : py::object(py::none());
    result["steps"] = table.arrays();
    result["summary"] = toPython(makeRunSummary(session.test(), stats, info));
    result["configuration"] = toPython(cfg.raw);
    result["out"] = dir ? py::object(py::str(dir->string())) : py::object(py::none());
    return result;
}

} // namespace

void bindRun(py::module_& m) {
    m.def("presets", &presetNames, "The preset names hsmu.run accepts (as `hsmu run` does).");
    m.def(
        "load_config", [](py::handle c) { return toPython(loadConfig(c).raw); }, py::arg("config"),
        "A configuration (preset name, path or dict) checked as `hsmu run` checks it, as a "
        "dict in its JSON shape. ValueError naming the file and field at fault.");
    m.def("run", &run, py::arg("config"), py::kw_only(), py::arg("ground_motion") = py::none(),
          py::arg("scale") = py::none(), py::arg("out") = py::none(),
          py::arg("progress") = py::none(),
          R"doc(Run a hybrid test headless on the built-in virtual specimens, as `hsmu run CONFIG
[--ground-motion FILE] [--scale S] [--out DIR]` does (the same session and stepping loop).

config: a preset name (hsmu.presets(), or shear-building-<N>[-elastic][-mass-damped]), a
configuration file, or a dict in the configuration's JSON shape (docs/configuration.md).
ground_motion: a record file replacing the configuration's; scale: its factor.
out: a folder for record.h5, steps.csv and summary.json as `hsmu run --out` writes them;
None writes nothing. progress: None or a callable given {"step", "total_steps", "time_s"}
about every 1 % (from the run's thread, with the GIL held).

Returns a dict: "status" ("finished", "held", "failed"), "interrupted" (Ctrl+C),
"hold_reason", "steps" ({column: float64 array}, one row per committed step, the columns of
steps.csv with their units in the names: time_s, ag_m_s2, <dof>_u_m, ..., at full
precision), "summary" (summary.json's content), "configuration" (dict), "out".
The GIL is released while the test runs. Ctrl+C is an emergency hold: every site holds, the
run ends cleanly with its record and summary written, and "status" is "held".
Raises ValueError naming the file and field for a bad configuration.)doc");
}

} // namespace hsmu::python
