// Link benchmarks (docs/benchmarks.md): the native protocol over loopback against the
// virtual controller (ControllerServer on a thread of this process, fast pace):
//   BM_TargetRoundTrip     target -> measurement round trip, per step (TCP_NODELAY);
//                          median and p99 in the counters (target: median <= 100 us)
//   BM_LinkStep            a whole step through TcpControl (target, measurement, commit, ack)
//   BM_HybridTestOverLink  paper-condition-3, 10 s record, as fast as possible over the link,
//                          against BM_HybridTestInProcess
//   BM_SimAppRoundTrip     OpenFresco SimApp against hsmu-controller's OfServer (fast pace):
//                          [3, trial] + [6] -> reply per step, median and p99 (docs/openfresco.md)
//   BM_SimAppStep          a whole step through SimAppControl (3, 6 -> reply, 5)
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
#include "core/test/HybridTest.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <thread>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

TestConfig condition3(double duration) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return parseConfig(j, "paper-condition-3.json");
}

/// A controller serving the preset's specimen on 127.0.0.1:<any port>, on its own thread.
class LocalController {
public:
    explicit LocalController(bool realTime) {
        const TestConfig cfg = condition3(10.0);
        std::vector<std::unique_ptr<SpecimenStation>> st;
        st.push_back(std::make_unique<SpecimenStation>(
            0, cfg.elements[0], ControllerSettings{},
            realTime ? SpecimenStation::Pace::RealTime : SpecimenStation::Pace::Fast, nullptr));
        ControllerServerOptions o;
        o.realTime = realTime;
        if (const char* prio = std::getenv("HSMU_BENCH_REALTIME_PRIORITY"))
            o.realTimePriority = std::atoi(prio); // SCHED_FIFO for the controller's loop
        o.quiet = true;
        m_server = std::make_unique<ControllerServer>(o, std::move(st));
        std::string error;
        if (!m_server->listen(error))
            std::fprintf(stderr, "%s\n", error.c_str());
        m_thread = std::thread([this] { m_server->run(); });
    }
    ~LocalController() { stop(); }
    std::uint16_t port() const { return m_server->port(); }
    ControllerStatistics stop() {
        m_server->stop();
        if (m_thread.joinable())
            m_thread.join();
        return m_server->statistics();
    }

private:
    std::unique_ptr<ControllerServer> m_server;
    std::thread m_thread;
};

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

double percentile(std::vector<double> v, double p) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * double(v.size() - 1))];
}

void BM_TargetRoundTrip(benchmark::State& state) {
    LocalController ctl(false);
    LinkClient link;
    std::string e;
    if (!link.connect("127.0.0.1", ctl.port(), 10.0, e) || !link.send(HelloMsg{1, 1, "", ""}, e) ||
        !link.receive(10.0, e) || !link.send(ConfigureMsg{0.01}, e) || !link.receive(10.0, e)) {
        state.SkipWithError(e.c_str());
        return;
    }
    std::vector<double> rtt;
    std::uint64_t n = 0;
    for (auto _ : state) {
        ++n;
        const double d = 1e-3 * std::sin(0.01 * double(n));
        const auto t0 = std::chrono::steady_clock::now();
        link.send(TargetMsg{n, d}, e);
        const auto m = link.receive(10.0, e);
        const auto t1 = std::chrono::steady_clock::now();
        const double s = std::chrono::duration<double>(t1 - t0).count();
        state.SetIterationTime(s);
        rtt.push_back(s);
        if (!m || !std::holds_alternative<MeasurementMsg>(*m)) {
            state.SkipWithError("no measurement");
            return;
        }
        link.send(CommitMsg{n}, e);
        link.receive(10.0, e);
    }
    state.counters["median_us"] = percentile(rtt, 0.5) * 1e6;
    state.counters["p99_us"] = percentile(rtt, 0.99) * 1e6;
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
BENCHMARK(BM_HybridTestOverLink)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_HybridTestInProcess)->UseRealTime()->Unit(benchmark::kMillisecond);

void BM_RealTimeDeadlines(benchmark::State& state) {
    const char* env = std::getenv("HSMU_BENCH_REALTIME_SECONDS");
    const double seconds = env ? std::atof(env) : 0.0;
    if (!(seconds > 0.0)) {
        state.SkipWithError("set HSMU_BENCH_REALTIME_SECONDS=60 to run the real-time pace");
        return;
    }
    for (auto _ : state) {
        LocalController ctl(true);
        TcpControl c("127.0.0.1", ctl.port(), "", {}, TcpControlOptions{});
        if (!c.prepare(0.01).ok) {
            state.SkipWithError("prepare failed");
            return;
        }
        const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
        long n = 0;
        while (std::chrono::steady_clock::now() < end) {
            ++n;
            ControlMeasurement m;
            if (!c.setTarget(1e-3 * std::sin(0.01 * double(n))).ok || !c.measure(m).ok ||
                !c.commit().ok) {
                state.SkipWithError("step failed");
                return;
            }
        }
        const ControllerStatistics s = ctl.stop();
        state.counters["steps"] = double(n);
        state.counters["ticks"] = double(s.ticks);
        state.counters["deadline_misses"] = double(s.deadlineMisses);
        state.counters["max_lateness_us"] = s.maxLateness * 1e6;
    }
}
BENCHMARK(BM_RealTimeDeadlines)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace

BENCHMARK_MAIN();
