"""hsmu.run against `hsmu run` on a preset (steps, record, summary), configurations, Ctrl+C."""
import json
import os
import signal

import numpy as np
import pytest

import hsmu

PRESET = "paper-condition-3"


@pytest.fixture(scope="module")
def program_run(cli, tmp_path_factory):
    work = tmp_path_factory.mktemp("run")
    cli("run", PRESET, "--out", work / "cli", cwd=work)
    return work / "cli"


@pytest.fixture(scope="module")
def python_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("run-py") / "py"
    return hsmu.run(PRESET, out=out)


def read_steps_csv(path):
    with open(path) as f:
        header = f.readline().strip().split(",")
    return header, np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)


def test_steps_equal_hsmu_runs_steps_csv(program_run, python_run):
    header, table = read_steps_csv(program_run / "steps.csv")
    steps = python_run["steps"]
    assert python_run["status"] == "finished" and python_run["hold_reason"] is None
    assert list(steps) == header
    assert table.shape == (3001, len(header))
    for j, name in enumerate(header):
        # steps.csv holds each double to 10 significant digits ("%.10g"): the arrays, written
        # so, read back as the file's values exactly
        rounded = np.array([float(f"{x:.10g}") for x in steps[name]])
        np.testing.assert_array_equal(rounded, table[:, j], err_msg=name)


def test_steps_equal_the_programs_record_at_full_precision(program_run, python_run):
    rec = hsmu.Record(program_run / "record.h5")
    steps = python_run["steps"]
    assert rec.rows == len(steps["time_s"])
    for array, dataset in (("time_s", "time"), ("ag_m_s2", "ground_acceleration"),
                           ("DOF 1_u_m", "u DOF 1"), ("DOF 2_a_m_s2", "a DOF 2"),
                           ("Element 1_force_kNm", "Element 1 force"),
                           ("Element 3_deformation_m", "Element 3 deformation"),
                           ("param_k0", "k0"), ("fit_error", "fit_error")):
        np.testing.assert_allclose(steps[array], rec[dataset], rtol=1e-12, atol=0,
                                   err_msg=array)


def test_out_folder_equals_the_programs(program_run, python_run):
    out = python_run["out"]
    assert open(os.path.join(out, "steps.csv")).read() == \
        (program_run / "steps.csv").read_text()
    ours = json.load(open(os.path.join(out, "summary.json")))
    theirs = json.loads((program_run / "summary.json").read_text())
    del ours["wall_time_s"], theirs["wall_time_s"]
    assert ours == theirs
    assert python_run["summary"]["steps"] == theirs["steps"] == 3000
    assert hsmu.Record(os.path.join(out, "record.h5")).rows == 3001


def test_a_dict_runs_as_the_preset(python_run):
    config = hsmu.load_config(PRESET)
    assert config["name"] == python_run["configuration"]["name"]
    config["analysis"]["duration"] = 2.0
    short = hsmu.run(config)
    assert short["status"] == "finished" and short["out"] is None
    n = len(short["steps"]["time_s"])
    assert 100 < n < 3001
    for name, values in short["steps"].items():
        np.testing.assert_array_equal(values, python_run["steps"][name][:n], err_msg=name)


def test_bad_configurations_give_the_programs_message(cli, tmp_path):
    config = hsmu.load_config(PRESET)
    config["analysis"]["dt"] = "fast"
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(config))
    done = cli("run", path, "--out", tmp_path / "out", check=False)
    assert done.returncode == 1
    with pytest.raises(ValueError) as from_file:
        hsmu.run(path)
    assert done.stderr.strip() == "hsmu run: " + str(from_file.value)
    assert "analysis" in str(from_file.value) and str(path) in str(from_file.value)
    with pytest.raises(ValueError, match="dt"):
        hsmu.run(config)
    done = cli("run", "no-such-preset", "--out", tmp_path / "out", check=False)
    with pytest.raises(ValueError) as unknown:
        hsmu.run("no-such-preset")
    assert done.stderr.strip() == "hsmu run: " + str(unknown.value)
    with pytest.raises(TypeError, match=r"config\['analysis'\]\['dt'\]"):
        hsmu.run({"analysis": {"dt": object()}})


def test_ctrl_c_is_an_emergency_hold_and_a_clean_end(tmp_path):
    seen, sent = [], []

    def progress(p):
        seen.append(p["step"])
        if p["step"] >= 300 and not sent:
            sent.append(p["step"])
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl+C, once

    result = hsmu.run(PRESET, out=tmp_path / "held", progress=progress)
    assert result["status"] == "held" and result["interrupted"]
    assert "SIGINT" in result["hold_reason"]
    n = len(result["steps"]["time_s"])
    assert sent and sent[0] < n < 3001
    rec = hsmu.Record(tmp_path / "held" / "record.h5")
    assert rec.rows == n
    np.testing.assert_array_equal(rec["time"], result["steps"]["time_s"])
    assert any("SIGINT" in a["message"] for a in rec.alarms)
    summary = json.loads((tmp_path / "held" / "summary.json").read_text())
    assert summary["state"] == "Holding" or "hold" in summary["state"].lower()


def test_documented():
    for name in ("run", "presets", "load_config"):
        assert getattr(hsmu, name).__doc__
    assert "hsmu run" in hsmu.run.__doc__
