#!/usr/bin/env bash
# Crash safety of the run record, measured (docs/recording.md, "Measured: kill -9"):
# N runs of `hsmu run CONFIG --dt DT`, each SIGKILLed at a random moment; the script samples
# steps.csv's row count every 20 ms, then opens the record with `hsmu export` and reports per
# kill: rows in the record, rows in steps.csv, steps committed more than 1 s before the kill
# (a lower bound: steps.csv's rows 1 s before), and the shortfalls.
#   scripts/measure-kill9.sh [N] [DT]
# With OVER_LINK=1 each run goes over the native link to a fresh `hsmu-controller --pace fast`
# (started per kill on a free port).
# Needs build/bin/hsmu (HSMU_BIN to override) and python3.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
hsmu="${HSMU_BIN:-$here/build/bin/hsmu}"
n="${1:-20}"; dt="${2:-0.001}"; shift $(( $# >= 2 ? 2 : $# )) || true
config="$here/resources/presets/paper-condition-3.json"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
# A 300 s ground motion (0.1 g sines, two columns: time [s], acceleration [g]) so that a run
# at dt = 0.001 lasts several seconds of wall time and every kill lands mid-run.
python3 - "$work/long.txt" <<'PY'
import math, sys
with open(sys.argv[1], "w") as f:
    for i in range(30001):
        t = 0.01 * i
        f.write(f"{t:.2f} {0.1 * math.sin(2 * math.pi * 1.3 * t) * math.sin(math.pi * t / 300):.6f}\n")
PY
printf "%4s %8s %8s %8s %10s %10s %8s\n" kill "t[s]" record csv "csv-1s" "lost>1s" behind
worst_lost=0; worst_behind=0
for k in $(seq 1 "$n"); do
  out="$work/run$k"; rm -rf "$out"
  link=(); cpid=
  if [ "${OVER_LINK:-0}" = 1 ]; then
    rm -f "$work/ctl" # else the wait below can read the previous controller's port
    "$(dirname "$hsmu")/hsmu-controller" --config "$config" --port 0 --pace fast --quiet \
      > "$work/ctl" 2>&1 &
    cpid=$!
    for _ in $(seq 300); do grep -qs listening "$work/ctl" && break; sleep 0.1; done
    port=$(sed -n 's/.*listening on [0-9.]*:\([0-9]*\).*/\1/p' "$work/ctl")
    link=(--controller "tcp://127.0.0.1:$port")
  fi
  "$hsmu" run "$config" --out "$out" --dt "$dt" --ground-motion "$work/long.txt" "${link[@]}" \
    >"$work/hsmu.log" 2>&1 &
  pid=$!
  delay=$(python3 -c "import random; print(round(random.uniform(0.3, ${KILL_MAX:-6.0}), 3))")
  python3 - "$out/steps.csv" "$delay" "$pid" > "$work/samples" <<'PY'
import os, signal, sys, time
path, delay, pid = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
w0 = time.monotonic() # the clock starts with the run's first rows (start-up varies with load)
while not os.path.exists(path) and time.monotonic() - w0 < 60: time.sleep(0.01)
t0 = time.monotonic(); samples = []
def rows():
    try:
        with open(path, 'rb') as f: return max(0, sum(1 for _ in f) - 1)
    except OSError: return 0
while time.monotonic() - t0 < delay:
    samples.append((time.monotonic(), rows())); time.sleep(0.02)
tk = time.monotonic()
try: os.kill(pid, signal.SIGKILL)
except ProcessLookupError: pass
before = max([r for t, r in samples if t <= tk - 1.0] or [0])
print(f"{tk - t0:.3f} {before}")
PY
  wait "$pid" 2>/dev/null || true # "Killed" is expected
  if [ -n "$cpid" ]; then kill "$cpid" 2>/dev/null || true; wait "$cpid" 2>/dev/null || true; fi
  read -r t before < "$work/samples"
  if [ ! -f "$out/steps.csv" ]; then
    echo "kill $k: the run wrote no steps.csv:"; tail -3 "$work/hsmu.log" "$work/ctl" 2>/dev/null || true
    continue
  fi
  csv=$(( $(wc -l < "$out/steps.csv") - 1 ))
  if (( csv <= 0 )); then
    echo "kill $k: killed before the first step:"; tail -2 "$work/hsmu.log" "$work/ctl" 2>/dev/null || true
    continue
  fi
  rec=-1
  if "$hsmu" export "$out/record.h5" --csv "$work/x$k" >/dev/null 2>&1; then
    f="$work/x$k/steps.csv" # rows counted like the run's steps.csv: lines after the header
    [ -f "$f" ] && rec=$(( $(wc -l < "$f") - 1 ))
  fi
  lost=$(( before > rec ? before - rec : 0 )); behind=$(( csv > rec ? csv - rec : 0 ))
  (( lost > worst_lost )) && worst_lost=$lost; (( behind > worst_behind )) && worst_behind=$behind
  printf "%4d %8s %8d %8d %10d %10d %8d\n" "$k" "$t" "$rec" "$csv" "$before" "$lost" "$behind"
done
echo "worst: $worst_lost steps committed > 1 s before the kill missing; record at most $worst_behind rows behind steps.csv"
