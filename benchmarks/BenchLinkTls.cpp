// The link benchmarks over tls:// (docs/benchmarks.md, "TLS links"): the same loops as
// BM_TargetRoundTrip and BM_RealTimeDeadlines (LinkBenchSupport.h), the link in TLS 1.3 with
// certificates on both ends, made once per run by scripts/hsmu-certs.sh in a temporary folder.
//   BM_TargetRoundTripTls     target -> measurement round trip; target: median <= the
//                             plaintext median + 20 us
//   BM_RealTimeDeadlinesTls   the 1024 Hz real-time pace over TLS (HSMU_BENCH_REALTIME_SECONDS,
//                             HSMU_BENCH_REALTIME_PRIORITY as for BM_RealTimeDeadlines)
#include "LinkBenchSupport.h"

#include <cstdlib>
#include <string>
#include <utility>

using namespace hsmu;
using namespace hsmu::comms;

namespace {

/// {controller, console} certificates of one lab CA; nullptr if the tool failed.
const std::pair<TlsSpec, TlsSpec>* certificates() {
    static std::pair<TlsSpec, TlsSpec> specs;
    static const bool made = [] {
        char dir[] = "/tmp/hsmu-bench-tls-XXXXXX";
        if (!mkdtemp(dir))
            return false;
        const std::string d = dir, tool = "bash " HSMU_SOURCE_DIR "/scripts/hsmu-certs.sh ";
        const std::string quiet = " > /dev/null";
        if (std::system((tool + "init-ca " + d + "/ca" + quiet).c_str()) != 0 ||
            std::system(
                (tool + "issue controller --ca " + d + "/ca --ip 127.0.0.1 --out " + d + quiet)
                    .c_str()) != 0 ||
            std::system((tool + "issue console --ca " + d + "/ca --out " + d + quiet).c_str()) != 0)
            return false;
        for (auto [spec, name] :
             {std::pair{&specs.first, "controller"}, {&specs.second, "console"}}) {
            spec->ca = d + "/ca/ca.pem";
            spec->certificate = d + "/" + name + ".pem";
            spec->key = d + "/" + name + ".key";
        }
        return true;
    }();
    return made ? &specs : nullptr;
}

void BM_TargetRoundTripTls(benchmark::State& state) {
    const auto* tls = certificates();
    if (!tls) {
        state.SkipWithError("scripts/hsmu-certs.sh failed (openssl missing?)");
        return;
    }
    LocalController ctl(false, nullptr, 0.0, &tls->first);
    LinkClientOptions o;
    o.tls = tls->second;
    LinkClient link(o);
    targetRoundTrips(state, link, ctl.port());
}
BENCHMARK(BM_TargetRoundTripTls)->UseManualTime()->Iterations(20000)->Unit(benchmark::kMicrosecond);

void BM_RealTimeDeadlinesTls(benchmark::State& state) {
    const auto* tls = certificates();
    if (!tls) {
        state.SkipWithError("scripts/hsmu-certs.sh failed (openssl missing?)");
        return;
    }
    realTimeDeadlines(state, tls);
}
BENCHMARK(BM_RealTimeDeadlinesTls)->Iterations(1)->Unit(benchmark::kSecond);

} // namespace
