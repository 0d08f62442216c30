#!/usr/bin/env python3
"""Benchmarks of the Python module (issue 28; docs/benchmarks.md "Python module"). Not a test.

  Law.drive over 10^6 samples of bmBoucWenStep's history and parameters (BenchCore.cpp):
      ns per sample, to set beside `hsmu_bench --benchmark_filter=bmBoucWenStep` (target:
      within 1.2x of it);
  a 10^5-row record (paper-condition-3 run for 1000 s) opened with hsmu.Record and every
      dataset read into arrays (target: <= 0.2 s): the median wall time of --repeat reads and
      the load average around them (the machine may be shared: say so with the figure).

Run: PYTHONPATH=build/python /usr/bin/python3 benchmarks/bench_python.py [--repeat 5]
"""
import argparse
import os
import tempfile
import time

import numpy as np

import hsmu


def best_of(repeat, work):
    """Best and median wall time [s], and the best CPU time of the process [s]."""
    times, cpu = [], []
    for _ in range(repeat):
        start, start_cpu = time.perf_counter(), time.process_time()
        work()
        times.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return min(times), float(np.median(times)), min(cpu)


def wall_of(repeat, work):
    """Every wall time [s], and the median CPU time of the process and of its children [s]
    (RecordReader first reads the file in a child process, RecordProbe)."""
    walls, cpu, children = [], [], []
    for _ in range(repeat):
        before, start = os.times(), time.perf_counter()
        work()
        walls.append(time.perf_counter() - start)
        after = os.times()
        cpu.append(after.user + after.system - before.user - before.system)
        children.append(after.children_user + after.children_system -
                        before.children_user - before.children_system)
    return walls, float(np.median(cpu)), float(np.median(children))


def load():
    """The load averages over 1, 5 and 15 minutes (as `uptime` prints them)."""
    return ", ".join(f"{x:.2f}" for x in os.getloadavg())


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()

    # bmBoucWenStep: the same parameters and the cyclic history 0.04 sin(2 pi i / 400) [rad]
    params = dict(k0=1.0, alpha=0.03, n=2.0, beta=2.5, gamma=0.5, deltaNu=0.03, deltaEta=0.03,
                  uRef=0.02, fRef=20.0)
    n = 1_000_000
    d = 0.04 * np.sin(2.0 * np.pi * np.arange(n) / 400.0)
    law = hsmu.Law("boucWen", **params)

    def drive():
        law.reset()
        law.drive(d)

    best, median, cpu = best_of(args.repeat, drive)
    print(f"Law.drive, boucWen, {n} samples: best {best * 1e3:.1f} ms "
          f"({best / n * 1e9:.1f} ns/sample), median {median / n * 1e9:.1f} ns/sample, "
          f"CPU {cpu / n * 1e9:.1f} ns/sample")

    with tempfile.TemporaryDirectory() as tmp:
        # a 1000 s record (PEER AT2, in g): the built-in 30 s synthetic record repeated
        ag = hsmu.run("paper-condition-3")["steps"]["ag_m_s2"][:3000] / 9.80665
        at2 = f"{tmp}/long.AT2"
        with open(at2, "w") as f:
            f.write("benchmark record\nsynthetic, repeated\nACCELERATION IN UNITS OF G\n")
            f.write("NPTS= 100000, DT= .01000 SEC\n")
            f.write("\n".join(f"{x:.7e}" for x in np.resize(ag, 100000)) + "\n")
        run = hsmu.run("paper-condition-3", ground_motion=at2, out=tmp)
        rows = len(run["steps"]["time_s"])
        path = f"{tmp}/record.h5"

        def read():
            rec = hsmu.Record(path)
            data = rec.data
            assert len(data["time"]) == rows

        read()  # the file in the page cache, as after the run that wrote it
        load_before = load()
        walls, cpu, children = wall_of(args.repeat, read)
        columns = len(hsmu.Record(path).names)
        print(f"hsmu.Record + .data, {rows} rows x {columns} datasets: wall median of "
              f"{len(walls)} {float(np.median(walls)):.3f} s (each: "
              f"{', '.join(f'{w:.3f}' for w in walls)}), best {min(walls):.3f} s; CPU median "
              f"{cpu:.3f} s + {children:.3f} s in the probe child; load average before "
              f"{load_before}, after {load()}")
        best, median, cpu = best_of(args.repeat, lambda: hsmu.Record(path))
        print(f"  of which hsmu.Record(path) (the reader): best {best:.3f} s, CPU {cpu:.3f} s")


if __name__ == "__main__":
    main()
