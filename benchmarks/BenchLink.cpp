// Link benchmarks (docs/benchmarks.md): the native protocol over loopback against the
// virtual controller (ControllerServer on a thread of this process, fast pace):
//   BM_TargetRoundTrip     target -> measurement round trip, per step (TCP_NODELAY);
//                          median and p99 in the counters (target: median <= 100 us)
//   BM_LinkStep            a whole step through TcpControl (target, measurement, commit, ack)
//   BM_HybridTestOverLink  paper-condition-3, 10 s record, as fast as possible over the link,
//                          against BM_HybridTestInProcess
//   BM_SitesStep/N         a HybridTest step with N = 1, 2, 4 specimens at N sites, each
//                          answering 0.5 ms late (--reply-delay): target 4 sites <= 1.3 x 1 site
//   BM_SimAppRoundTrip     OpenFresco SimApp against hsmu-controller's OfServer (fast pace):
//                          [3, trial] + [6] -> reply per step, median and p99 (docs/openfresco.md)
//   BM_SimAppStep          a whole step through SimAppControl (3, 6 -> reply, 5)
//   BM_OpenSeesGenericClient  the real OpenSees (../shared/tools/opensees; skipped where absent)
//                          as the client: `element genericClient` -> OfServer (SimApp element
//                          server, fast pace), an SDOF Bouc-Wen under El Centro, each step
//                          timed inside OpenSees; median and p99 per step (target <= 0.5 ms)
//   BM_OpenSeesGenericTcp  the same through OpenFresco's `expControl GenericTCP` -> OfServer
//                          (GenericTCP server)
//   BM_EmergencyHoldLatency  HybridTest::emergencyHold() from another thread while the step
//                          thread is blocked on a site that read its target and went silent
//                          (tests/comms/SilentSite.h): time until the Hold frame has arrived
//                          at the site; median and max in the counters (target <= 50 ms)
//   BM_TargetRoundTripTls, BM_RealTimeDeadlinesTls: the same over tls:// (BenchLinkTls.cpp)
//   BM_RealTimeDeadlines   the real-time pace for HSMU_BENCH_REALTIME_SECONDS seconds (default
//                          skipped): deadline misses of the 1024 Hz loop (target 0);
//                          HSMU_BENCH_REALTIME_PRIORITY=P runs the loop under SCHED_FIFO P
#include "comms/controller/ControllerServer.h"
#include "comms/controller/OfServer.h"
#include "comms/link/ControlFactory.h"
#include "comms/link/LinkClient.h"
#include "comms/openfresco/OfFrame.h"
#include "comms/openfresco/OfSocket.h"
#include "comms/openfresco/SimAppControl.h"
#include "core/config/ConfigLoader.h"
#include "core/experiment/HybridTest.h"

#include "../tests/comms/SilentSite.h"
#include "LinkBenchSupport.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

/// hsmu-controller's SimApp element server for the preset's specimen, on its own thread.
class LocalSimAppServer {
public:
    LocalSimAppServer() {
        const TestConfig cfg = condition3(10.0);
        std::vector<std::unique_ptr<SpecimenStation>> st;
        st.push_back(std::make_unique<SpecimenStation>(0, cfg.elements[0], ControllerSettings{},
                                                       SpecimenStation::Pace::Fast, nullptr));
        OfServerOptions o;
        o.realTime = false;
        o.quiet = true;
        m_server = std::make_unique<OfServer>(o, std::move(st));
        std::string error;
        if (!m_server->listen(error))
            std::fprintf(stderr, "%s\n", error.c_str());
        m_thread = std::thread([this] { m_server->run(); });
    }
    ~LocalSimAppServer() {
        m_server->stop();
        m_thread.join();
    }
    std::uint16_t port() const { return m_server->port(); }

private:
    std::unique_ptr<OfServer> m_server;
    std::thread m_thread;
};

void BM_TargetRoundTrip(benchmark::State& state) {
    LocalController ctl(false);
    LinkClient link;
    targetRoundTrips(state, link, ctl.port());
}
BENCHMARK(BM_TargetRoundTrip)->UseManualTime()->Iterations(20000)->Unit(benchmark::kMicrosecond);

/// One full step per iteration through a prepared control: target, measure, commit.
void stepThrough(benchmark::State& state, ExperimentalControl& c) {
    long n = 0;
    for (auto _ : state) {
        ++n;
        ControlMeasurement m;
        if (!c.setTarget(1e-3 * std::sin(0.01 * double(n))).ok || !c.measure(m).ok ||
            !c.commit().ok) {
            state.SkipWithError("step failed");
            return;
        }
    }
    state.SetItemsProcessed(n);
}

void BM_LinkStep(benchmark::State& state) {
    LocalController ctl(false);
    TcpControl c("127.0.0.1", ctl.port(), "", {}, TcpControlOptions{});
    if (!c.prepare(0.01).ok) {
        state.SkipWithError("prepare failed");
        return;
    }
    stepThrough(state, c);
}
BENCHMARK(BM_LinkStep)->UseRealTime()->Unit(benchmark::kMicrosecond);

void BM_SimAppRoundTrip(benchmark::State& state) {
    LocalSimAppServer server;
    of::OfSocket socket;
    std::string e;
    const of::OfSizes sizes; // ctrl disp 1, daq disp 1 + force 1, dataSize 256
    const auto header = of::encodeSizes(sizes);
    if (!socket.connect("127.0.0.1", server.port(), 10.0, e) ||
        !socket.write(header.data(), header.size(), 10.0, e)) {
        state.SkipWithError(e.c_str());
        return;
    }
    std::vector<std::uint8_t> trial, get, commit, reply(sizes.dataSize * sizeof(double));
    of::encodeRequest(of::Action::GetDaqResponse, {}, sizes.dataSize, get, e);
    of::encodeRequest(of::Action::CommitState, {}, sizes.dataSize, commit, e);
    std::vector<double> rtt;
    long n = 0;
    for (auto _ : state) {
        ++n;
        const double d[] = {1e-3 * std::sin(0.01 * double(n))};
        of::encodeRequest(of::Action::SetTrialResponse, d, sizes.dataSize, trial, e);
        const auto t0 = std::chrono::steady_clock::now();
        const bool ok = socket.write(trial.data(), trial.size(), 10.0, e) &&
                        socket.write(get.data(), get.size(), 10.0, e) &&
                        socket.read(reply.data(), reply.size(), 10.0, e);
        const auto t1 = std::chrono::steady_clock::now();
        if (!ok || !socket.write(commit.data(), commit.size(), 10.0, e)) {
            state.SkipWithError(e.c_str());
            return;
        }
        const double s = std::chrono::duration<double>(t1 - t0).count();
        state.SetIterationTime(s);
        rtt.push_back(s);
    }
    state.counters["median_us"] = percentile(rtt, 0.5) * 1e6;
    state.counters["p99_us"] = percentile(rtt, 0.99) * 1e6;
}
BENCHMARK(BM_SimAppRoundTrip)->UseManualTime()->Iterations(20000)->Unit(benchmark::kMicrosecond);

void BM_SimAppStep(benchmark::State& state) {
    LocalSimAppServer server;
    of::OfControlOptions o;
    o.logConnect = false;
    of::SimAppControl c("127.0.0.1", server.port(), "Element 1", o);
    if (!c.prepare(0.01).ok) {
        state.SkipWithError("prepare failed");
        return;
    }
    stepThrough(state, c);
}
BENCHMARK(BM_SimAppStep)->UseRealTime()->Unit(benchmark::kMicrosecond);

void runHybrid(benchmark::State& state, bool overLink) {
    const TestConfig cfg = condition3(10.0);
    long steps = 0;
    for (auto _ : state) {
        state.PauseTiming();
        std::unique_ptr<LocalController> ctl;
        ControlFactory f;
        if (overLink) {
            ctl = std::make_unique<LocalController>(false);
            f = makeControlFactory(LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", ctl->port()});
        }
        auto test = buildHybridTest(cfg, f);
        state.ResumeTiming();
        if (!test->prepare()) {
            state.SkipWithError(test->lastError().c_str());
            return;
        }
        while (test->step() == HybridTest::StepResult::Advanced) {
        }
        steps += test->currentStep();
        state.PauseTiming();
        test.reset();
        ctl.reset();
        state.ResumeTiming();
    }
    state.SetItemsProcessed(steps);
}

void BM_HybridTestOverLink(benchmark::State& state) {
    runHybrid(state, true);
}
void BM_HybridTestInProcess(benchmark::State& state) {
    runHybrid(state, false);
}
void BM_EmergencyHoldLatency(benchmark::State& state) {
    const TestConfig cfg = condition3(10.0);
    TcpControlOptions o;
    o.stepDeadline = 60.0;
    o.silenceTimeout = 120.0;
    std::vector<double> latency;
    for (auto _ : state) {
        SilentSite site(3, true);
        auto test = buildHybridTest(
            cfg, makeControlFactory(LinkAddress{LinkAddress::Kind::Tcp, "127.0.0.1", site.port()}, o));
        if (!test->prepare()) {
            state.SkipWithError(test->lastError().c_str());
            return;
        }
        std::atomic<bool> done{false};
        std::thread stepper([&] {
            while (test->step() == HybridTest::StepResult::Advanced) {
            }
            done = true;
        });
        site.watch(&done);
        if (!site.waitSilent(30.0)) {
            state.SkipWithError("the site never went silent");
            stepper.join();
            return;
        }
        const auto t0 = SilentSite::Clock::now();
        test->emergencyHold("benchmark");
        const bool arrived = site.waitHolds(1, 30.0);
        stepper.join();
        if (!arrived || site.stepReturnedAtFirstHold()) {
            state.SkipWithError("the hold did not arrive while the step was blocked");
            return;
        }
        const double s = std::chrono::duration<double>(site.firstHoldAt() - t0).count();
        latency.push_back(s);
        state.SetIterationTime(s);
    }
    std::sort(latency.begin(), latency.end());
    if (!latency.empty()) {
        state.counters["median_us"] = latency[latency.size() / 2] * 1e6;
        state.counters["max_us"] = latency.back() * 1e6;
    }
}
BENCHMARK(BM_EmergencyHoldLatency)->UseManualTime()->Iterations(50)->Unit(benchmark::kMicrosecond);

BENCHMARK(BM_HybridTestOverLink)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HybridTestInProcess)->UseRealTime()->Unit(benchmark::kMillisecond);

/// N independent Bouc-Wen SDOFs, each specimen at a site of its own.
nlohmann::json sitesModel(int n) {
    const nlohmann::json law = {
        {"law", "boucWen"}, {"k0", 40.0}, {"alpha", 0.05}, {"n", 1.5},       {"gamma", 100.0},
        {"beta", 300.0},    {"A0", 1.0},  {"deltaA", 0.0}, {"deltaNu", 0.2}, {"deltaEta", 0.2}};
    nlohmann::json dofs = nlohmann::json::array(), elements = nlohmann::json::array();
    for (int i = 1; i <= n; ++i) {
        const std::string k = std::to_string(i);
        dofs.push_back({{"name", "DOF " + k}, {"mass", 1.0}});
        elements.push_back({{"name", "Spring " + k},
                            {"type", "lateralSpring"},
                            {"dof", "DOF " + k},
                            {"material", law},
                            {"experimental", true},
                            {"specimen", {{"material", law}}}});
    }
    return {{"structure", {{"dofs", dofs}, {"elements", elements}}},
            {"analysis", {{"dt", 0.01}}}};
}

// Step time of a HybridTest whose N specimens are at N sites (ControllerServers on threads of
// this process, loopback, fast pace), each site answering 0.5 ms after the target arrives
// (--reply-delay). Sequential dispatch would cost N x 0.5 ms; send-all / acquire-all costs
// about one. Counters: median and p99 step time [us], wall clock per step.
void BM_SitesStep(benchmark::State& state) {
    const int n = int(state.range(0));
    constexpr double kReplyDelay = 0.5e-3;
    nlohmann::json j = sitesModel(n);
    const TestConfig plain = parseConfig(j, "sites.json");
    std::vector<std::unique_ptr<LocalController>> labs;
    for (int i = 0; i < n; ++i) {
        labs.push_back(std::make_unique<LocalController>(false, &plain.elements[std::size_t(i)],
                                                         kReplyDelay));
        j["sites"].push_back({{"name", "Lab " + std::to_string(i + 1)},
                              {"address", "tcp://127.0.0.1:" + std::to_string(labs.back()->port())},
                              {"elements", {"Spring " + std::to_string(i + 1)}}});
    }
    const TestConfig cfg = parseConfig(j, "sites.json");
    auto test = buildHybridTest(cfg, makeControlFactory(LinkAddress{}, TcpControlOptions{}, cfg));
    if (!test->prepare()) {
        state.SkipWithError(test->lastError().c_str());
        return;
    }
    std::vector<double> times;
    for (auto _ : state) {
        const auto t0 = std::chrono::steady_clock::now();
        const auto r = test->step();
        const auto t1 = std::chrono::steady_clock::now();
        if (r != HybridTest::StepResult::Advanced) {
            state.SkipWithError(("step: " + test->lastError() +
                                 (test->alarms().empty() ? "" : test->alarms().back().message))
                                    .c_str());
            return;
        }
        const double s = std::chrono::duration<double>(t1 - t0).count();
        state.SetIterationTime(s);
        times.push_back(s);
    }
    state.counters["median_us"] = percentile(times, 0.5) * 1e6;
    state.counters["p99_us"] = percentile(times, 0.99) * 1e6;
}
BENCHMARK(BM_SitesStep)
    ->Arg(1)
    ->Arg(2)
    ->Arg(4)
    ->UseManualTime()
    ->Iterations(1000)
    ->Unit(benchmark::kMicrosecond);

/// An OfServer of the given protocol serving a Bouc-Wen spring (the OpenSees SDOF's), fast pace.
class SdofOfServer {
public:
    explicit SdofOfServer(of::OfProtocol protocol) {
        const nlohmann::json law = {
            {"law", "boucWen"}, {"k0", 40.0}, {"alpha", 0.05}, {"n", 1.5},       {"gamma", 100.0},
            {"beta", 300.0},    {"A0", 1.0},  {"deltaA", 0.0}, {"deltaNu", 0.2}, {"deltaEta", 0.2}};
        const nlohmann::json j = {{"structure",
                                   {{"dofs", {{{"name", "DOF 1"}, {"mass", 1.0}}}},
                                    {"elements",
                                     {{{"name", "Spring"},
                                       {"type", "lateralSpring"},
                                       {"dof", "DOF 1"},
                                       {"material", law},
                                       {"experimental", true},
                                       {"specimen", {{"material", law}}}}}}}},
                                  {"analysis", {{"dt", 0.01}}}};
        const TestConfig cfg = parseConfig(j, "sdof.json");
        std::vector<std::unique_ptr<SpecimenStation>> st;
        st.push_back(std::make_unique<SpecimenStation>(0, cfg.elements[0], ControllerSettings{},
                                                       SpecimenStation::Pace::Fast, nullptr));
        OfServerOptions o;
        o.protocol = protocol;
        o.realTime = false;
        o.quiet = true;
        m_server = std::make_unique<OfServer>(o, std::move(st));
        std::string error;
        if (!m_server->listen(error))
            std::fprintf(stderr, "%s\n", error.c_str());
        m_thread = std::thread([this] { m_server->run(); });
    }
    ~SdofOfServer() {
        m_server->stop();
        m_thread.join();
    }
    std::uint16_t port() const { return m_server->port(); }

private:
    std::unique_ptr<OfServer> m_server;
    std::thread m_thread;
};

/// Run `tcl` in the real OpenSees (under `timeout`), stdin from `input`; its output.
std::string runOpenSees(const std::string& tcl, const std::string& input, bool& ok) {
    const std::string dir = std::filesystem::temp_directory_path() / "hsmu_bench_opensees";
    std::filesystem::create_directories(dir);
    const std::string script = dir + "/bench.tcl";
    std::ofstream(script) << tcl;
    const std::string cmd = "printf '" + input + "' | timeout 600 " + std::string(HSMU_SOURCE_DIR) +
                            "/../shared/tools/opensees/opensees " + script + " 2>&1";
    std::string out;
    ok = false;
    if (FILE* f = popen(cmd.c_str(), "r")) {
        char buf[4096];
        while (std::fgets(buf, sizeof buf, f))
            out += buf;
        ok = pclose(f) == 0;
    }
    return out;
}

/// The SDOF with `element` as its spring, `steps` steps of dt 0.01 each timed by OpenSees;
/// prints "STEP_US median p99".
std::string timedSdof(const std::string& element, const std::string& extra, bool openFresco,
                      int steps) {
    const std::string gm =
        std::string(HSMU_SOURCE_DIR) + "/../shared/tools/opensees/examples/elcentro_NS_accel_g.txt";
    std::string s = "wipe\nmodel BasicBuilder -ndm 1 -ndf 1\n";
    if (openFresco)
        s += "loadPackage OpenFrescoTcl\n";
    s += "node 1 0.0\nnode 2 0.0 -mass 1.0\nfix 1 1\n" + extra + element + "\n";
    s += "timeSeries Path 1 -dt 0.02 -filePath {" + gm + "} -factor 9.80665\n";
    s += "pattern UniformExcitation 1 1 -accel 1\nrayleigh 0.25298221281347039 0 0 0\n";
    s += "constraints Plain\nnumberer Plain\nsystem FullGeneral\nalgorithm Linear\n";
    s += "integrator NewmarkExplicit 0.5\nanalysis Transient\nset times {}\n";
    s += "for {set i 0} {$i < " + std::to_string(steps) + "} {incr i} {\n";
    s += "  set t0 [clock microseconds]\n  analyze 1 0.01\n";
    s += "  lappend times [expr {[clock microseconds] - $t0}]\n}\n";
    s += "set st [lsort -integer $times]\nset k [llength $st]\n";
    s += "puts \"STEP_US [lindex $st [expr {$k / 2}]] [lindex $st [expr {int(0.99 * ($k - "
         "1))}]]\"\n";
    if (openFresco)
        s += "wipeExp\n";
    s += "wipe\n";
    return s;
}

void reportOpenSeesSteps(benchmark::State& state, const std::string& out, bool ok) {
    const auto at = out.find("STEP_US ");
    double median = 0.0, p99 = 0.0;
    if (!ok || at == std::string::npos ||
        std::sscanf(out.c_str() + at, "STEP_US %lf %lf", &median, &p99) != 2) {
        state.SkipWithError(
            ("OpenSees run failed: " + out.substr(out.size() > 600 ? out.size() - 600 : 0))
                .c_str());
        return;
    }
    state.counters["median_us_per_step"] = median;
    state.counters["p99_us_per_step"] = p99;
}

bool openSeesAbsent(benchmark::State& state) {
    const std::string exe = std::string(HSMU_SOURCE_DIR) + "/../shared/tools/opensees/opensees";
    if (std::filesystem::exists(exe))
        return false;
    state.SkipWithError(("the real OpenSees is not at " + exe).c_str());
    return true;
}

/// Steps per OpenSees run (HSMU_BENCH_OPENSEES_STEPS, default 1000 = 10 s of El Centro).
int openSeesSteps() {
    const char* env = std::getenv("HSMU_BENCH_OPENSEES_STEPS");
    return env ? std::max(10, std::atoi(env)) : 1000;
}

void BM_OpenSeesGenericClient(benchmark::State& state) {
    if (openSeesAbsent(state))
        return;
    for (auto _ : state) {
        SdofOfServer server(of::OfProtocol::SimApp);
        bool ok = false;
        const std::string out =
            runOpenSees(timedSdof("element genericClient 1 -node 2 -dof 1 -server " +
                                      std::to_string(server.port()) + " 127.0.0.1 -dataSize 256",
                                  "", false, openSeesSteps()),
                        "", ok);
        reportOpenSeesSteps(state, out, ok);
    }
}
BENCHMARK(BM_OpenSeesGenericClient)->Iterations(1)->Unit(benchmark::kSecond);

void BM_OpenSeesGenericTcp(benchmark::State& state) {
    if (openSeesAbsent(state))
        return;
    for (auto _ : state) {
        SdofOfServer server(of::OfProtocol::GenericTcp);
        bool ok = false;
        const std::string extra =
            "expControl GenericTCP 1 127.0.0.1 " + std::to_string(server.port()) +
            " -ctrlModes 1 0 0 0 0 -daqModes 1 0 0 1 0\n"
            "expSetup OneActuator 1 -control 1 1 -sizeTrialOut 1 1\nexpSite LocalSite 1 1\n";
        const std::string out =
            runOpenSees(timedSdof("expElement twoNodeLink 1 1 2 -dir 1 -site 1 -initStif 40.0",
                                  extra, true, openSeesSteps()),
                        "\\n\\n", ok);
        reportOpenSeesSteps(state, out, ok);
    }
}
BENCHMARK(BM_OpenSeesGenericTcp)->Iterations(1)->Unit(benchmark::kSecond);

void BM_RealTimeDeadlines(benchmark::State& state) {
    realTimeDeadlines(state, nullptr);
}
BENCHMARK(BM_RealTimeDeadlines)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

BENCHMARK_MAIN();
