"""hsmu.Record reading a record that another process is still writing (SWMR,
docs/recording.md "Writing, flushing and crash safety"; docs/python.md "Records").

The writer is a real `hsmu run` against a real `hsmu-controller` at real-time pace (about
10 ms a step, so the run lasts seconds). The test synchronises on what it can observe: each
progress line the run prints on stderr; at each one it freezes the writer (SIGSTOP) so that
the file cannot change while it is read, reads, and lets it go on (SIGCONT). Once the reader
has seen rows while the run was still going, the run is let finish; refresh() then reads every
row, equal to the finished record opened afresh.
"""
import os
import signal
import subprocess

import numpy as np

import hsmu

PRESET = "paper-condition-3"
DURATION = "5"  # s of test time: 501 rows


def frozen(process):
    """Context: the writer stopped (SIGSTOP) while the body runs, continued after."""
    class Frozen:
        def __enter__(self):
            os.kill(process.pid, signal.SIGSTOP)

        def __exit__(self, *exc):
            os.kill(process.pid, signal.SIGCONT)
    return Frozen()


def test_a_record_being_written_reads_a_consistent_prefix_then_every_row(controllers, tmp_path):
    controller = controllers(PRESET, pace="realtime")
    out = tmp_path / "run"
    path = out / "record.h5"
    run = subprocess.Popen(
        [os.environ["HSMU_CLI"], "run", PRESET, "--controller", controller.address,
         "--duration", DURATION, "--out", str(out)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
    rec, seen, lines, partial, opened_again = None, [], [], None, 0
    try:
        for line in run.stderr:  # "hsmu run: connecting ...", then " 5 %  t = ...", ...
            lines.append(line)
            if "%" not in line or "100 %" in line or not path.exists():
                continue
            with frozen(run):
                if rec is None:
                    rec = hsmu.Record(path)
                    assert rec.swmr
                else:
                    # a second Record of the same file opened while the first is open (HDF5
                    # shares the file within a process) reads what is on disk now, as the
                    # first does after refresh()
                    again = hsmu.Record(path)
                    rec.refresh()
                    assert again.rows == rec.rows, (again.rows, rec.rows)
                    opened_again += 1
                    del again
                seen.append(rec.rows)
                if partial is None and rec.rows > 1:
                    # mid-run: every dataset the same rows, no half row
                    lengths = {name: len(rec[name]) for name in rec.names}
                    assert set(lengths.values()) == {rec.rows}, lengths
                    partial = {name: rec[name].copy() for name in rec.names}
                elif partial is not None and rec.rows > len(partial["time"]):
                    break  # the reader saw the file grow: enough
        out_text, err_text = run.communicate()
    finally:
        if run.poll() is None:
            run.kill()
            run.wait()
    assert run.returncode == 0, "".join(lines) + err_text
    assert partial is not None and opened_again >= 2, (seen, "".join(lines))
    assert 1 < len(partial["time"]) < seen[-1] < int(DURATION) * 100 + 1  # read while written

    added = rec.refresh()  # after the run: every row
    rows = int(DURATION) * 100 + 1
    assert rec.rows == rows and added == rows - seen[-1]
    refreshed = {name: rec[name].copy() for name in rec.names}
    alarms, events = rec.alarms, rec.events
    assert rec.refresh() == 0  # nothing more
    for name, values in partial.items():  # the prefix read mid-run is the finished record's
        np.testing.assert_array_equal(values, refreshed[name][:len(values)], err_msg=name)
    del rec
    final = hsmu.Record(path)  # the finished record opened afresh
    assert final.rows == rows and final.names == list(refreshed)
    for name in final.names:
        np.testing.assert_array_equal(refreshed[name], final[name], err_msg=name)
    assert alarms == final.alarms and events == final.events


def test_refresh_of_a_finished_record_adds_nothing(cli, tmp_path):
    cli("run", PRESET, "--duration", "1", "--out", tmp_path / "done")
    rec = hsmu.Record(tmp_path / "done" / "record.h5")
    assert rec.rows == 101
    assert rec.refresh() == 0 and rec.rows == 101
