#pragma once
// What the link benchmarks share (BenchLink.cpp, BenchLinkTls.cpp): the preset's configuration,
// a controller on a thread of this process (plain or TLS), and the measuring loops, so that the
// plaintext and TLS figures come from the very same code.
#include "comms/controller/ControllerServer.h"
#include "comms/link/LinkClient.h"
#include "comms/link/TcpControl.h"
#include "core/config/ConfigLoader.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <thread>

namespace hsmu::comms {

inline TestConfig condition3(double duration) {
    std::ifstream in(std::string(HSMU_SOURCE_DIR) + "/resources/presets/paper-condition-3.json");
    nlohmann::json j = nlohmann::json::parse(in);
    j["analysis"]["duration"] = duration;
    return parseConfig(j, "paper-condition-3.json");
}

/// A controller serving the preset's specimen on 127.0.0.1:<any port>, on its own thread.
class LocalController {
public:
    /// specimen: the element served (default: the preset's); replyDelay [s]: the site's added
    /// latency (ControllerServerOptions::replyDelay).
    explicit LocalController(bool realTime, const ElementSpec* specimen = nullptr,
                             double replyDelay = 0.0, const TlsSpec* tls = nullptr) {
        const TestConfig cfg = condition3(10.0);
        std::vector<std::unique_ptr<SpecimenStation>> st;
        st.push_back(std::make_unique<SpecimenStation>(
            0, specimen ? *specimen : cfg.elements[0], ControllerSettings{},
            realTime ? SpecimenStation::Pace::RealTime : SpecimenStation::Pace::Fast, nullptr));
        ControllerServerOptions o;
        o.realTime = realTime;
        o.replyDelay = replyDelay;
        if (const char* prio = std::getenv("HSMU_BENCH_REALTIME_PRIORITY"))
            o.realTimePriority = std::atoi(prio); // SCHED_FIFO for the controller's loop
        o.quiet = true;
        if (tls)
            o.tls = *tls;
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

inline double percentile(std::vector<double> v, double p) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    return v[static_cast<std::size_t>(p * double(v.size() - 1))];
}

/// Target -> measurement round trips over link (connected here to port), per iteration;
/// median and p99 in the counters.
inline void targetRoundTrips(benchmark::State& state, LinkClient& link, std::uint16_t port) {
    std::string e;
    if (!link.connect("127.0.0.1", port, 10.0, e) || !link.send(HelloMsg{1, 1, "", ""}, e) ||
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

/// The real-time pace for HSMU_BENCH_REALTIME_SECONDS seconds through TcpControl (over TLS
/// when tls: {server, console}); the controller's deadline misses in the counters.
inline void realTimeDeadlines(benchmark::State& state, const std::pair<TlsSpec, TlsSpec>* tls) {
    const char* env = std::getenv("HSMU_BENCH_REALTIME_SECONDS");
    const double seconds = env ? std::atof(env) : 0.0;
    if (!(seconds > 0.0)) {
        state.SkipWithError("set HSMU_BENCH_REALTIME_SECONDS=60 to run the real-time pace");
        return;
    }
    for (auto _ : state) {
        LocalController ctl(true, nullptr, 0.0, tls ? &tls->first : nullptr);
        TcpControlOptions options;
        if (tls)
            options.tls = tls->second;
        TcpControl c("127.0.0.1", ctl.port(), "", {}, options);
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

} // namespace hsmu::comms
