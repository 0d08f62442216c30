#include "gui/cli/RunFlow.h"

#include "comms/link/ControlFactory.h"
#include "core/config/RecordConfig.h"
#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "gui/cli/CliText.h"
#include "gui/cli/RunReport.h"
#include "gui/cli/SignalHold.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <system_error>

namespace hsmu::gui {

namespace {

/// One line on stderr (unbuffered: in order with whatever the front end printed).
void errLine(const std::string& line) {
    std::fputs((line + '\n').c_str(), stderr);
}

std::string num(double x, int digits = 4) {
    return number(x, 'g', digits);
}

/// Progress on stderr about every 5 %: percent, test time, steps/s.
class Progress final : public StepObserver {
public:
    explicit Progress(const HybridTest& test) : m_test(test) {}
    void onStep(const StepRecord& row) override {
        if (row.step == 0)
            return;
        const int percent = int(100.0 * row.step / std::max(1, m_test.totalSteps()));
        if (percent < m_next && row.step < m_test.totalSteps())
            return;
        const double seconds = std::max(
            1e-9,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count());
        errLine(Text(translate("RunCommand", "%1 %  t = %2 s  %3 steps/s"))
                    .arg(percent, 3)
                    .arg(number(row.time, 'f', 2))
                    .arg(number(row.step / seconds, 'f', 0)));
        m_next = (percent / 5 + 1) * 5;
    }

private:
    const HybridTest& m_test;
    const std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now();
    int m_next = 5;
};

/// QDir().mkpath(dir): true if dir exists as a folder afterwards.
bool makePath(const std::string& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    return std::filesystem::is_directory(dir, ec);
}

} // namespace

int RunFlow::fail(const std::string& message) {
    errLine("hsmu run: " + message);
    return 1;
}

std::string RunFlow::printedDir(const std::string& outDir) {
    // QDir's path(): the text given, one trailing '/' removed (not from "/"), "" as ".".
    if (outDir.empty())
        return ".";
    if (outDir.size() > 1 && outDir.back() == '/')
        return outDir.substr(0, outDir.size() - 1);
    return outDir;
}

int RunFlow::exec(const RunRequest& r) {
    TestConfig cfg;
    std::unique_ptr<HybridTest> test;
    try {
        cfg = loadConfigOrPreset(r.config, r.presets);
        if (r.configure)
            r.configure(cfg);
        if (!r.approval.empty()) {
            if (!cfg.updating.enabled)
                errLine(
                    translate("RunCommand",
                              "hsmu run: --approval ignored: the configuration has no updating"));
            cfg.updating.approval = r.approval;
        }
        if (r.recordDofs) { // the same parser as the configuration's record.dofs
            try {
                cfg.record.dofs = configDofList(cfg, *r.recordDofs);
            } catch (const std::invalid_argument& e) {
                throw std::runtime_error(std::string("--record-dofs: ") + e.what());
            }
        }
        if (r.recordEvery > 0)
            cfg.record.every = r.recordEvery;
        comms::TcpControlOptions link; // the session's timeouts (LinkTimeouts), the token
        link.token = r.token;
        test = buildHybridTest(cfg, comms::makeControlFactory(r.controller, link, cfg));
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    if (!makePath(r.outDir))
        return fail(
            Text(translate("RunCommand", "%1: cannot create the output directory")).arg(r.outDir));
    HeadlessOptions headless;
    headless.outDir = r.outDir;
    headless.csv = r.csv;
    headless.reconnect.attempts = r.reconnect;
    headless.deflate = r.deflate;
    headless.siteSecurity = comms::siteSecurity(r.controller, cfg);
    // Folder, steps.csv, the HDF5 record (docs/recording.md, flushed at least twice a second),
    // statistics and summary.json: core/session/HeadlessRun, as hsmu.run in Python.
    std::unique_ptr<HeadlessRun> headlessRun;
    try {
        headlessRun = std::make_unique<HeadlessRun>(cfg, std::move(test), headless);
    } catch (const std::exception& e) {
        return fail(e.what());
    }
    if (const std::size_t columns = headlessRun->csvSkippedColumns())
        errLine(
            Text(translate("RunCommand",
                           "hsmu run: steps.csv not written (%1 columns); record.h5 holds every "
                           "column (hsmu export writes CSV from it)"))
                .arg(columns));
    TestSession& session = headlessRun->session();
    HybridTest* const run = &session.test();
    if (r.observe)
        r.observe(session);
    session.onReconnect = [run](const TestSession::Reconnect& c) {
        errLine(
            Text(translate("RunCommand",
                           "hsmu run: link fault at t = %1 s (step %2): %3; reconnecting in %4 s "
                           "(attempt %5 of %6)"))
                .arg(num(run->time(), 6))
                .arg(run->currentStep())
                .arg(c.reason)
                .arg(num(c.delay, 3))
                .arg(c.attempt)
                .arg(c.of));
    };

    if (r.controller.kind != comms::LinkAddress::Kind::Builtin)
        errLine(Text(translate("RunCommand", "hsmu run: connecting to %1 (%2 protocol, %3)"))
                    .args({r.controller.toString(), comms::linkProtocol(r.controller, cfg.link),
                           r.controller.security()}));
    // SIGINT / SIGTERM from here on hold every site out of band (even mid-step); the
    // session never resumes an operator hold.
    SignalHold signalHold(*run);
    if (!headlessRun->prepare())
        return fail(Text(translate("RunCommand", "the test cannot start: %1"))
                        .arg(headlessRun->lastError()));

    Progress progress(*run);
    session.addObserver(&progress);
    const TestSession::Status result = headlessRun->runToEnd();
    session.removeObserver(&progress);

    int code = result == TestSession::Status::Finished ? 0 : 1;
    if (result == TestSession::Status::Held) {
        code = 2;
        errLine(Text(translate("RunCommand", "hsmu run: test held at t = %1 s (step %2): %3"))
                    .arg(num(run->time(), 6))
                    .arg(run->currentStep())
                    .arg(holdReason(*run).value_or("held")));
    } else if (code != 0) {
        errLine(Text(translate("RunCommand", "hsmu run: the test stopped unexpectedly (state %1)"))
                    .arg(testStateName(run->state())));
    }
    const HeadlessRun::Failures failed = headlessRun->finish();
    if (!failed.record.empty())
        code = fail(failed.record);
    if (!failed.stepsCsv.empty())
        code = fail(Text(translate("RunCommand", "%1: write failed")).arg(failed.stepsCsv));
    if (!failed.summary.empty())
        code = fail(failed.summary);
    if (r.afterRun && r.afterRun(headlessRun->layout(), cfg) != 0)
        code = 1;
    const std::string report =
        RunReport::text(*run, headlessRun->statistics(), headlessRun->info(), printedDir(r.outDir));
    std::fputs(report.c_str(), stdout);
    std::fflush(stdout);
    return code;
}

} // namespace hsmu::gui
