#include "python/PyRun.h"

#include "comms/link/ControlFactory.h"
#include "core/config/ConfigLoader.h"
#include "core/config/PresetCatalog.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "core/output/StepCsvWriter.h"
#include "core/session/HeadlessRun.h"
#include "core/util/SecretFile.h"
#include "python/PyArrays.h"
#include "python/PyInterrupt.h"
#include "python/PyJson.h"

#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>

namespace py = pybind11;
namespace fs = std::filesystem;

namespace hsmu::python {

namespace {

std::string fspath(py::handle path) {
    return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

/// The presets of `hsmu run`, as folders: beside an installed module
/// (PREFIX/lib/python3/dist-packages -> PREFIX/share/hsmu/presets), else the source tree's.
PresetCatalog presets() {
    const fs::path module = py::module_::import("hsmu").attr("__file__").cast<std::string>();
    return presetFolders(
        {(module.parent_path() / "../../../share/hsmu/presets").string(), HSMU_SOURCE_PRESETS});
}

/// The rule of `hsmu run CONFIG` (core/config/PresetCatalog.h), or a dict.
TestConfig loadConfig(py::handle config) {
    if (py::isinstance<py::dict>(config))
        return parseConfig(toJson(config, "config"), "config (dict)");
    return loadConfigOrPreset(fspath(config), presets());
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

/// The link of `hsmu run --controller ADDRESS --token-file F` (docs/security.md).
ControlFactory controlFactory(const TestConfig& cfg, const std::string& controller,
                              py::handle tokenFile) {
    std::string error;
    const auto address = comms::LinkAddress::parse(controller, &error);
    if (!address)
        throw py::value_error("controller: " + error);
    const auto token = linkToken(tokenFile.is_none() ? std::string() : fspath(tokenFile), error);
    if (!token)
        throw py::value_error("token_file: " + error);
    comms::TcpControlOptions options;
    options.token = *token;
    return comms::makeControlFactory(*address, options, cfg);
}

py::dict run(py::handle config, py::handle groundMotion, py::handle scale, py::handle out,
             py::handle progress, const std::string& controller, py::handle tokenFile,
             int reconnect) {
    TestConfig cfg = loadConfig(config);
    if (!groundMotion.is_none()) { // as --ground-motion FILE (gui/ConfigOverrides)
        cfg.groundMotion.file = fs::absolute(fspath(groundMotion)).string();
        cfg.groundMotion.format = "auto";
        cfg.groundMotion.units.clear();
        cfg.groundMotion.dt = 0.0;
    }
    if (!scale.is_none())
        cfg.groundMotion.scale = scale.cast<double>();
    if (reconnect < 0)
        throw py::value_error("reconnect: expected a whole number >= 0, found " +
                              std::to_string(reconnect));
    HeadlessOptions options;
    options.outDir = out.is_none() ? std::string() : fspath(out);
    options.reconnect.attempts = reconnect;
    {
        std::string ignored;
        if (const auto address = comms::LinkAddress::parse(controller, &ignored))
            options.siteSecurity = comms::siteSecurity(*address, cfg);
    }
    std::unique_ptr<HybridTest> test =
        buildHybridTest(cfg, controlFactory(cfg, controller, tokenFile));
    std::unique_ptr<HeadlessRun> headless;
    try {
        headless = std::make_unique<HeadlessRun>(cfg, std::move(test), options);
    } catch (const std::runtime_error& e) { // the folder, steps.csv, the record
        throw py::value_error(e.what());
    }
    TestSession& session = headless->session();
    StepTable table(headless->layout(), session.test().totalSteps(), progress);
    session.addObserver(&table);
    TestSession::Status status = TestSession::Status::Failed;
    bool interrupted = false;
    bool started = false;
    {
        py::gil_scoped_release release; // connecting to a controller takes its time
        started = headless->prepare();
    }
    if (!started) {
        session.removeObserver(&table);
        throw py::value_error("the test cannot start: " + headless->lastError());
    }
    interrupted = runInterruptible([&] { status = headless->runToEnd(); },
                                   [&] { session.emergencyHold("SIGINT received"); }, false);
    session.removeObserver(&table);
    HeadlessRun::Failures failed;
    {
        py::gil_scoped_release release;
        failed = headless->finish();
    }
    if (!failed.record.empty())
        throw py::value_error(failed.record);
    if (!failed.stepsCsv.empty())
        throw py::value_error(failed.stepsCsv + ": write failed");
    if (!failed.summary.empty())
        throw py::value_error(failed.summary);

    py::dict result;
    result["status"] = statusName(status);
    result["interrupted"] = interrupted;
    const auto reason = holdReason(session.test());
    result["hold_reason"] = reason ? py::object(py::str(*reason)) : py::object(py::none());
    result["steps"] = table.arrays();
    result["summary"] =
        toPython(makeRunSummary(session.test(), headless->statistics(), headless->info()));
    result["configuration"] = toPython(cfg.raw);
    result["out"] =
        options.outDir.empty() ? py::object(py::none()) : py::object(py::str(options.outDir));
    return result;
}

} // namespace

void bindRun(py::module_& m) {
    m.def(
        "presets", [] { return presets().ids(); },
        "The preset names hsmu.run accepts (as `hsmu run` does).");
    m.def(
        "load_config", [](py::handle c) { return toPython(loadConfig(c).raw); }, py::arg("config"),
        "A configuration (preset name, path or dict) checked as `hsmu run` checks it, as a "
        "dict in its JSON shape. ValueError naming the file and field at fault.");
    m.def("run", &run, py::arg("config"), py::kw_only(), py::arg("ground_motion") = py::none(),
          py::arg("scale") = py::none(), py::arg("out") = py::none(),
          py::arg("progress") = py::none(), py::arg("controller") = "builtin",
          py::arg("token_file") = py::none(), py::arg("reconnect") = 0,
          R"doc(Run a hybrid test headless, as `hsmu run CONFIG [--ground-motion FILE]
[--scale S] [--out DIR] [--controller ADDRESS] [--token-file F] [--reconnect N]` does (the same
set-up, session and stepping loop: core/session/HeadlessRun).

config: a preset name (hsmu.presets(), or shear-building-<N>[-elastic][-mass-damped]), a
configuration file, or a dict in the configuration's JSON shape (docs/configuration.md).
ground_motion: a record file replacing the configuration's; scale: its factor.
out: a folder for record.h5, steps.csv and summary.json as `hsmu run --out` writes them;
None writes nothing. progress: None or a callable given {"step", "total_steps", "time_s"}
about every 1 % (from the run's thread, with the GIL held).
controller: "builtin" (the in-process virtual specimens, the default) or the address of an
actuator controller, "tcp://HOST:PORT" (hsmu-controller or a lab controller), "simapp://..."
or "generictcp://..." (docs/cli.md); the configuration's sites still apply. token_file: the
file holding the controller's token (chmod 600), else the environment variable
HSMU_CONTROLLER_TOKEN (docs/security.md). reconnect: automatic resumes after a link fault,
as --reconnect N (0: a lost controller holds the test).

Returns a dict: "status" ("finished", "held", "failed"), "interrupted" (Ctrl+C),
"hold_reason" (None, or the reason `hsmu run` prints in "test held at t = ... s (step N):
REASON", e.g. a lost controller), "steps" ({column: float64 array}, one row per committed
step, the columns of steps.csv with their units in the names: time_s, ag_m_s2, <dof>_u_m,
..., at full precision), "summary" (summary.json's content; its "link_security" says how
each site was reached: "tls", "plaintext-loopback", "insecure-plaintext", "builtin"),
"configuration" (dict), "out".
A held run (a lost controller, a limit, Ctrl+C) returns normally, with every committed step
kept and the record and summary written, as `hsmu run` exits 2 with them.
The GIL is released while the test connects, runs and writes its files. Ctrl+C is an
emergency hold: every site holds, the run ends cleanly with its record and summary written,
and "status" is "held".
Raises ValueError naming the file and field for a bad configuration, a bad controller address
or token file, or a controller that cannot be reached ("the test cannot start: ...", as `hsmu
run` exits 1).)doc");
}

} // namespace hsmu::python
