#!/usr/bin/env bash
# The cost of TLS on a link, measured in pairs (docs/benchmarks.md, "TLS links, paired"): each
# pair runs the plaintext and the TLS benchmark of hsmu_bench_link back to back, their order
# alternating from pair to pair, so that the load of a shared machine falls on both alike.
#
#   scripts/bench-tls-pairs.sh round-trip [PAIRS]   BM_TargetRoundTrip vs BM_TargetRoundTripTls
#       (20,000 target -> measurement round trips each): one line per pair with both medians
#       [us] and the load average at its start
#   scripts/bench-tls-pairs.sh realtime [PAIRS] [SECONDS]
#       BM_RealTimeDeadlines vs BM_RealTimeDeadlinesTls, the controller's 1024 Hz loop under
#       SCHED_FIFO 50 (needs CAP_SYS_NICE; refused otherwise, then the loop runs at normal
#       priority), SECONDS each (default 30): deadline misses, ticks, worst lateness
#
# The binary: $HSMU_BUILD_DIR/bin/hsmu_bench_link (default build/), a Release build.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bin="${HSMU_BUILD_DIR:-$here/build}/bin/hsmu_bench_link"
[ -x "$bin" ] || { echo "bench-tls-pairs.sh: build hsmu_bench_link first ($bin)" >&2; exit 2; }
mode="${1:-}"
pairs="${2:-6}"
load() { cut -d' ' -f1 /proc/loadavg; }

case "$mode" in
  round-trip)
    median() { "$bin" --benchmark_filter="^$1/" 2>/dev/null |
               sed -n "s/^$1\/.* median_us=\([0-9.]*\).*/\1/p"; }
    for i in $(seq 1 "$pairs"); do
      l="$(load)"
      if [ $((i % 2)) = 1 ]; then p="$(median BM_TargetRoundTrip)"; t="$(median BM_TargetRoundTripTls)"
      else t="$(median BM_TargetRoundTripTls)"; p="$(median BM_TargetRoundTrip)"; fi
      echo "pair $i: load $l, plaintext median $p us, TLS median $t us"
    done
    ;;
  realtime)
    export HSMU_BENCH_REALTIME_SECONDS="${3:-30}" HSMU_BENCH_REALTIME_PRIORITY=50
    one() { echo "$1: load $(load), $("$bin" --benchmark_filter="^$1/" 2>&1 |
            sed -n "s/^$1\/.* \(deadline_misses=.*\)/\1/p")"; }
    for i in $(seq 1 "$pairs"); do
      if [ $((i % 2)) = 1 ]; then one BM_RealTimeDeadlines; one BM_RealTimeDeadlinesTls
      else one BM_RealTimeDeadlinesTls; one BM_RealTimeDeadlines; fi
    done
    ;;
  *) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2 ;;
esac
