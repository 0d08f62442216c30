#!/usr/bin/env bash
# The strong SDOF as whole processes, hsmu against OpenSees 3.8 on the same model (issue 27
# item 4; docs/benchmarks.md, "The strong SDOF against OpenSees"): benchmarks/sdof-opensees.json
# against ../shared/tools/opensees/examples/sdof_reference.tcl with DT=0.001 (31,160 steps of
# El Centro, explicit Newmark, a Bouc-Wen spring), run alternately N times each. Each process's
# CPU time (user + sys) and wall time are its rusage from wait4(), unrounded (/usr/bin/time
# rounds CPU to 10 ms, a fifth of hsmu's run); each runs under /usr/bin/time, whose %M is its
# peak RSS: a child forked from this Python script would inherit Python's ~14 MiB as its peak
# (the kernel keeps the high-water mark across exec); /usr/bin/time's own few hundred
# microseconds of CPU count for both programs alike. Prints each
# run, the medians, the CPU ratio and the load average before and after. Exits 0 without
# measuring when the kit is absent.
#   scripts/bench-sdof-opensees.sh [N]          (default 5)
# Needs build/bin/hsmu (HSMU_BIN to override) and python3. hsmu writes its record and steps.csv
# (HSMU_ARGS adds options, e.g. "--csv none"); OpenSees its two recorders.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kit="$here/../shared/tools/opensees"
if [ ! -x "$kit/opensees" ]; then
    echo "bench-sdof-opensees: no OpenSees kit at $kit; nothing measured"
    exit 0
fi
HSMU_BIN="${HSMU_BIN:-$here/build/bin/hsmu}" HERE="$here" KIT="$kit" N="${1:-5}" \
python3 - <<'PY'
import os, shutil, statistics, subprocess, tempfile
here, kit, n = os.environ["HERE"], os.environ["KIT"], int(os.environ["N"])
work = tempfile.mkdtemp()
def run(args, cwd, env):
    rss = os.path.join(work, "rss")
    args = ["/usr/bin/time", "-f", "%M", "-o", rss] + args
    with open(os.path.join(work, "log"), "w") as log:
        p = subprocess.Popen(args, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT)
        import time
        t0 = time.monotonic()
        _, status, ru = os.wait4(p.pid, 0)
        wall = time.monotonic() - t0
    if status != 0:
        raise SystemExit(f"{args[0]} failed: " + open(os.path.join(work, "log")).read()[-800:])
    return ru.ru_utime + ru.ru_stime, wall, int(open(rss).read().split()[-1]) / 1024.0
hsmu = [os.environ["HSMU_BIN"], "run", os.path.join(here, "benchmarks/sdof-opensees.json"),
        "--out", os.path.join(work, "hsmu")] + os.environ.get("HSMU_ARGS", "").split()
ose = [os.path.join(kit, "opensees"), "sdof_reference.tcl"]
print("load before:", open("/proc/loadavg").read().strip())
runs = {"hsmu": [], "opensees": []}
try:
    for i in range(n):
        shutil.rmtree(os.path.join(work, "hsmu"), ignore_errors=True)
        runs["hsmu"].append(run(hsmu, here, os.environ))
        out = os.path.join(work, "os")
        shutil.rmtree(out, ignore_errors=True)
        env = dict(os.environ, DT="0.001", OUTDIR=out)
        runs["opensees"].append(run(ose, os.path.join(kit, "examples"), env))
        if not os.path.getsize(os.path.join(out, "disp.out")):
            raise SystemExit("OpenSees wrote no disp.out")
finally:
    shutil.rmtree(work, ignore_errors=True)
print("load after: ", open("/proc/loadavg").read().strip())
for who, r in runs.items():
    for cpu, wall, rss in r:
        print(f"{who:9s} cpu {cpu:.4f} s  wall {wall:.3f} s  peak rss {rss:.1f} MiB")
med = {w: [statistics.median(x[k] for x in r) for k in range(3)] for w, r in runs.items()}
for who, (cpu, wall, rss) in med.items():
    print(f"median {who:9s} cpu {cpu:.4f} s  wall {wall:.3f} s  peak rss {rss:.1f} MiB")
h, o = med["hsmu"], med["opensees"]
print(f"OpenSees / hsmu: cpu {o[0] / h[0]:.2f}x, wall {o[1] / h[1]:.2f}x; "
      f"peak rss hsmu - OpenSees {h[2] - o[2]:+.1f} MiB")
PY
