#!/usr/bin/env bash
# Every acceptance figure of issue 27 in one go, for a quiet minute on the lab machine
# (docs/benchmarks.md, "Whole runs and the recording"): medians of N (default 5) whole
# processes, each measured by its rusage from wait4() (what /usr/bin/time prints, unrounded).
#   1. `hsmu run shear-building-1000 --duration 1` and `shear-building-10000 --duration 1`
#      (1,000 steps, record included): the loop per step (summary.json wall_time_s / steps),
#      the whole process per step (wall), its CPU (user + sys) and peak RSS; quiet, then with
#      two busy cores in the background (`sh -c 'while :; do :; done'` x2, killed after).
#   2. The 10,000-DOF record: bytes per step, uncompressed and with --compress 1.
#   3. The strong SDOF against OpenSees 3.8 (scripts/bench-sdof-opensees.sh N), when the kit
#      is present.
# Prints the load average before and after each part. Targets (issue 27): loop and process
# <= 0.2 ms/step at 1,000 DOFs and <= 1.5 ms/step at 10,000 DOFs on a quiet machine, no worse
# than 2x those under the two busy cores; SDOF >= 3x OpenSees in CPU, peak RSS <= OpenSees'.
#   scripts/bench-whole-runs.sh [N]
# Needs build/bin/hsmu (HSMU_BIN to override) and python3; writes only under a temporary folder.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
n="${1:-5}"
HSMU_BIN="${HSMU_BIN:-$here/build/bin/hsmu}" N="$n" python3 - <<'PY'
import json, os, shutil, statistics, subprocess, tempfile, time
hsmu, n = os.environ["HSMU_BIN"], int(os.environ["N"])
work = tempfile.mkdtemp()
def load():
    return " ".join(open("/proc/loadavg").read().split()[:3])
def run(preset, extra=()):
    out = os.path.join(work, "out")
    shutil.rmtree(out, ignore_errors=True)
    t0 = time.monotonic()
    p = subprocess.Popen([hsmu, "run", preset, "--duration", "1", "--out", out, *extra],
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, ru = os.wait4(p.pid, 0)
    wall = time.monotonic() - t0
    err = p.stderr.read().decode(errors="replace")
    if status != 0:
        raise SystemExit(f"hsmu run {preset} failed: {err[-800:]}")
    summary = json.load(open(os.path.join(out, "summary.json")))
    steps = summary.get("steps") or 1000
    record = os.path.getsize(os.path.join(out, "record.h5"))
    return {"loop": summary["wall_time_s"] / steps * 1e3, "process": wall / steps * 1e3,
            "cpu": ru.ru_utime + ru.ru_stime, "rss": ru.ru_maxrss / 1024.0,
            "record": record / steps / 1e3}
def report(label, runs):
    med = {k: statistics.median(r[k] for r in runs) for k in runs[0]}
    span = {k: (min(r[k] for r in runs), max(r[k] for r in runs)) for k in runs[0]}
    print(f"  {label}: loop {med['loop']:.3f} ms/step ({span['loop'][0]:.3f}-{span['loop'][1]:.3f}), "
          f"process {med['process']:.3f} ms/step ({span['process'][0]:.3f}-{span['process'][1]:.3f}), "
          f"CPU {med['cpu']:.3f} s, peak RSS {med['rss']:.1f} MiB, record {med['record']:.1f} kB/step")
def busy(k):
    return [subprocess.Popen(["sh", "-c", "while :; do :; done"]) for _ in range(k)]
try:
    for preset in ("shear-building-1000", "shear-building-10000"):
        print(f"{preset} --duration 1 (medians of {n}); load before {load()}")
        report("quiet", [run(preset) for _ in range(n)])
        hogs = busy(2)
        try:
            report("two busy cores", [run(preset) for _ in range(n)])
        finally:
            for h in hogs:
                h.kill()
                h.wait()
        print(f"  load after {load()}")
    print(f"shear-building-10000 --duration 1 --compress 1 (medians of {n}); load before {load()}")
    report("compressed", [run("shear-building-10000", ["--compress", "1"]) for _ in range(n)])
    print(f"  load after {load()}")
finally:
    shutil.rmtree(work, ignore_errors=True)
PY
echo "strong SDOF against OpenSees (scripts/bench-sdof-opensees.sh $n):"
"$here/scripts/bench-sdof-opensees.sh" "$n"
