// Step-rate check (issue 6): the test worker's steps per second with every console plot live
// against headless. Target: the live rate within 10 % of the headless one.
//   StepRate/Headless     HybridTest::step() in a plain loop (as `hsmu run` without --plots)
//   StepRate/Worker       the same test on the console's TestController / TestWorker thread at
//                         full speed, rows drained at ~30 Hz but drawn nowhere
//   StepRate/LivePlots    the console's MainWindow (LivePlotsPanel: hysteresis + auxiliary
//                         model + twin, force, displacement, ground motion with cursor,
//                         tracking, fit error, 7 parameter plots) shown offscreen at
//                         1600 x 1000, every batch appended and replotted
//   Panel/Redraw          one redraw of the full panel holding the whole run (GUI thread)
// The test: preset paper-condition-3 (UKF updating) at dt = 0.002 s (15001 rows), so that
// the plots hold as many points as a long lab test. Counter steps_per_s = steps / wall time.
// Run: QT_QPA_PLATFORM=offscreen build/bin/hsmu_bench_step_rate --benchmark_repetitions=3

#include "core/config/TestFactory.h"
#include "core/experiment/HybridTest.h"
#include "gui/ConfigOverrides.h"
#include "gui/PresetLibrary.h"
#include "gui/app/MainWindow.h"
#include "gui/app/TestController.h"
#include "gui/cli/RecordCollector.h"
#include "gui/plots/LivePlotsPanel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QEventLoop>

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace hsmu;
using namespace hsmu::gui;

const QString kPreset = QStringLiteral("paper-condition-3");
constexpr double kDt = 0.002; // [s]

ConfigOverrides overrides() {
    ConfigOverrides o;
    o.dt = kDt;
    return o;
}

TestConfig config() {
    TestConfig cfg = PresetLibrary::load(kPreset);
    overrides().applyTo(cfg);
    return cfg;
}

/// Runs the event loop until the controller's test finished (or failed); returns steps.
int runToEnd(TestController& controller) {
    QEventLoop loop;
    QObject::connect(&controller, &TestController::stateChanged, &loop,
                     [&loop](RunState s, const QString&) {
                         if (s == RunState::Finished || s == RunState::Failed ||
                             s == RunState::Holding || s == RunState::Stopped)
                             loop.quit();
                     });
    controller.start();
    loop.exec();
    return int(controller.recordsDelivered()) - 1; // minus the initial state
}

void reportRate(benchmark::State& state, double steps) {
    state.counters["steps_per_s"] = benchmark::Counter(steps, benchmark::Counter::kIsRate);
}

void headless(benchmark::State& state) {
    const TestConfig cfg = config();
    double steps = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        std::unique_ptr<HybridTest> test = buildHybridTest(cfg);
        test->prepare();
        state.ResumeTiming();
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        steps += test->currentStep();
    }
    reportRate(state, steps);
}

void worker(benchmark::State& state) {
    const TestConfig cfg = config();
    double steps = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        TestController controller;
        controller.setSpeed(0.0);
        controller.load(cfg);
        state.ResumeTiming();
        steps += runToEnd(controller);
    }
    reportRate(state, steps);
}

void livePlots(benchmark::State& state) {
    double steps = 0.0;
    for (auto _ : state) {
        state.PauseTiming();
        MainWindow window(overrides());
        window.resize(1600, 1000);
        window.setSpeed(0.0);
        window.show();
        window.loadConfiguration(kPreset);
        QCoreApplication::processEvents();
        state.ResumeTiming();
        steps += runToEnd(window.controller());
    }
    reportRate(state, steps);
}

/// The GUI thread's price of one redraw of the whole panel holding the full run (15001
/// rows per series), shown offscreen at 1600 x 1000: rescale, draw, paint.
void panelRedraw(benchmark::State& state) {
    const TestConfig cfg = config();
    std::unique_ptr<HybridTest> test = buildHybridTest(cfg);
    RecordCollector rows;
    test->addObserver(&rows);
    test->prepare();
    while (test->step() == HybridTest::StepResult::Advanced) {
    }
    LivePlotsPanel panel;
    panel.configure(RunLayout::of(*test), cfg);
    panel.appendRecords(rows.records());
    panel.resize(1600, 1000);
    panel.show();
    QCoreApplication::processEvents();
    for (auto _ : state) {
        panel.refreshNow();
        panel.repaint();
    }
    state.counters["rows"] = double(rows.records().size());
}

BENCHMARK(headless)->Name("StepRate/Headless")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(worker)->Name("StepRate/Worker")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(livePlots)->Name("StepRate/LivePlots")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(panelRedraw)->Name("Panel/Redraw")->Unit(benchmark::kMillisecond);

} // namespace

int main(int argc, char** argv) {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM") && qEnvironmentVariableIsEmpty("DISPLAY"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv))
        return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
