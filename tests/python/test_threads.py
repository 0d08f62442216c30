"""The GIL released by long calls, their callbacks run with it held, and Ctrl+C (SIGINT)
stopping a long calibration or identification cleanly (docs/python.md, "Threads and
interrupts").

How the GIL test knows: the call runs on a worker thread whose progress callback is
`events.append`, a C function (no bytecode, so no point where the interpreter could hand the
GIL over), while this thread appends ticks to the same list. Ticks found between the first and
the last progress dict were appended while the worker was inside the engine: a call that kept
the GIL between its callbacks would leave none there. Only counts are compared, never times.
"""
import itertools
import os
import signal
import threading

import numpy as np
import pytest

import hsmu

PRESET = "paper-condition-3"
MODEL = {"uRef": 0.02, "fRef": 40.0}  # the normalisation of the law that made the history
TRUTH = {"k0": 2.5, "alpha": 0.04, "n": 2.0}


@pytest.fixture(scope="module")
def history():
    """A Bouc-Wen specimen over 20,000 samples of a growing cycle (m, kN): a calibration of
    about 2 s of CPU (18 starts, 2,275 replays)."""
    n = 20_000
    t = np.arange(n) * 0.01
    d = 0.05 * (0.2 + 0.8 * t / t[-1]) * np.sin(2 * np.pi * t / 4.0)
    law = hsmu.Law("boucWen", **TRUTH, **MODEL)
    return t, d, law.drive(d)


def ticks_inside(call):
    """Run call(progress) on a worker thread while this thread ticks. Returns the call's
    result, the progress dicts and the ticks appended between the first and the last dict."""
    events, result, done = [], {}, threading.Event()

    def worker():
        try:
            result["value"] = call(events.append)
        except BaseException as e:  # noqa: B902 - handed to the test thread
            result["error"] = e
        finally:
            done.set()

    thread = threading.Thread(target=worker)
    thread.start()
    while not done.is_set():
        events.append(sum(range(100)))  # a tick: a little Python work, then an int
    thread.join()
    if "error" in result:
        raise result["error"]
    marks = [i for i, e in enumerate(events) if isinstance(e, dict)]
    assert len(marks) >= 2, f"{len(marks)} progress calls"
    ticks = sum(1 for e in events[marks[0]:marks[-1]] if not isinstance(e, dict))
    return result["value"], [events[i] for i in marks], ticks


def test_calibrate_releases_the_gil(history):
    t, d, f = history
    result, progress, ticks = ticks_inside(
        lambda p: hsmu.calibrate(t, d, f, law="boucWen", model=MODEL, progress=p))
    # the calibration reports each minimization ("calibration", repeated), then "done"
    phases = [p["phase"] for p in progress]
    assert [x for i, x in enumerate(phases) if i == 0 or phases[i - 1] != x] == ["calibration", "done"]
    assert ticks > 0, "no other Python thread ran while the calibration ran"
    # the calibration itself is not disturbed: the law it was generated with
    for name, value in TRUTH.items():
        assert result["model"][name] == pytest.approx(value, rel=1e-9), name
    assert result["nrmse"] < 1e-12


def test_identify_releases_the_gil(history):
    t, d, f = history
    n = 4_000
    result, progress, ticks = ticks_inside(
        lambda p: hsmu.identify(t[:n], d[:n], f[:n], method="ukf", progress=p))
    assert progress[-1]["phase"] == "done" and progress[-1]["samples_done"] == n
    assert len(progress) > 10  # every 64 samples of the online pass
    assert ticks > 0, "no other Python thread ran while the identification ran"
    assert len(result["parameters"]["k0"]) == n


def test_run_releases_the_gil():
    result, progress, ticks = ticks_inside(lambda p: hsmu.run(PRESET, progress=p))
    assert result["status"] == "finished"
    assert [p["step"] for p in progress][-1] == 3000 and len(progress) >= 100
    assert ticks > 0, "no other Python thread ran while the test ran"
    steps = result["steps"]["time_s"]
    assert len(steps) == 3001


def test_callbacks_run_python_with_the_gil(history):
    """A Python callback (bytecode, objects made and freed) on the engine's thread: it needs
    the GIL, which the call takes back for it."""
    t, d, f = history
    seen = []

    def progress(p):
        seen.append({k: v for k, v in p.items()} | {"thread": threading.get_ident()})

    hsmu.identify(t[:2000], d[:2000], f[:2000], method="ukf", progress=progress)
    assert seen[-1]["phase"] == "done"
    assert threading.get_ident() not in {s["thread"] for s in seen}  # the engine's thread


@pytest.mark.parametrize("call", ["calibrate", "identify"])
def test_ctrl_c_stops_a_long_call_and_the_module_stays_usable(history, call):
    t, d, f = history
    short = slice(0, 3000)
    reference = hsmu.calibrate(t[short], d[short], f[short])
    phases = []

    def progress(p):
        phases.append(p["phase"])
        if len(phases) == 1:
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl+C once, at the start

    with pytest.raises(KeyboardInterrupt):
        if call == "calibrate":
            hsmu.calibrate(t, d, f, model=MODEL, progress=progress)
        else:
            hsmu.identify(t, d, f, method="ukf", progress=progress)
    # stopped at its next check: the call never reached its end
    assert "done" not in phases
    if call == "identify":  # online progress every 64 samples: it stopped within the pass
        assert phases.count("online") < len(t) // 64
    # nothing left behind: the same calls give the same results, a run runs
    again = hsmu.calibrate(t[short], d[short], f[short])
    assert again["model"] == reference["model"] and again["nrmse"] == reference["nrmse"]
    assert hsmu.run(PRESET)["status"] == "finished"


def test_the_measure_sees_a_call_that_keeps_the_gil():
    """The control: C code that keeps the GIL between two progress entries (list.extend over
    a C iterator: an entry, 3*10^7 items filtered out, an entry) leaves no tick between them,
    so the ticks found above come from the engine letting the GIL go."""
    first, last = {"phase": "first"}, {"phase": "last"}

    def holds_the_gil(progress):
        target = progress.__self__  # the list whose append is the progress callback
        target.extend(itertools.chain([first], filter(None, itertools.repeat(0, 30_000_000)),
                                      [last]))
        return None

    _, progress, ticks = ticks_inside(holds_the_gil)
    assert progress == [first, last]
    assert ticks == 0
