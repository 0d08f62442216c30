"""hsmu.calibrate / identify / read_measured against `hsmu replay --import` on a shared record."""
import json
import os
import signal

import numpy as np
import pytest

import hsmu

RECORD = "hysteresis/rc-column-soesianawati-unit1/soesianawati_unit1.txt"


@pytest.fixture(scope="module")
def column(shared_data):
    path = shared_data / RECORD
    if not path.exists():
        pytest.skip(f"{path} absent: the calibration comparison needs it")
    return path


def assert_same(a, b, where="calibration"):
    """Every number equal to 1e-12 relative, every other value equal (dicts, lists)."""
    if isinstance(b, dict):
        assert sorted(a) == sorted(b), where
        for k in b:
            assert_same(a[k], b[k], f"{where}.{k}")
    elif isinstance(b, list):
        assert len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same(x, y, f"{where}[{i}]")
    elif isinstance(b, float) and not isinstance(b, bool):
        assert a == pytest.approx(b, rel=1e-12, abs=1e-300), where
    else:
        assert a == b, where


def replay(cli, tmp_path, data, *args):
    out = tmp_path / "replay"
    cli("replay", "--import", data, "--out", out, *args)
    return out


def test_read_measured_is_the_programs_import(cli, tmp_path, column):
    m = hsmu.read_measured(column)
    out = replay(cli, tmp_path, column, "--method", "ukf")
    table = np.genfromtxt(out / "parameters.csv", delimiter=",", skip_header=1)
    assert m["units"] == ("s", "m", "kN") and len(m["time"]) == 548
    for i, key in enumerate(("time", "deformation", "force")):
        np.testing.assert_array_equal(m[key], table[:, i])


def test_calibrate_equals_hsmu_replay_calibration(cli, tmp_path, column):
    m = hsmu.read_measured(column)
    out = replay(cli, tmp_path, column, "--method", "calibration")
    summary = json.loads((out / "summary.json").read_text())
    expected = summary["calibration"]
    result = hsmu.calibrate(m["time"], m["deformation"], m["force"], units=m["units"])
    del result["seconds"], expected["seconds"]  # wall time
    assert result.pop("law") == "boucWen"
    assert result.pop("verdict") == summary["verdict"]
    units = result.pop("units")
    assert units["deformation"] == "m" and units["force"] == "kN"
    assert {k: units[k] for k in summary["parameterUnits"]} == summary["parameterUnits"]
    assert_same(result, expected)
    assert 0 < result["nrmse"] < 1 and result["parameters"]["k0"]["ci95"][0] < \
        result["parameters"]["k0"]["value"] < result["parameters"]["k0"]["ci95"][1]


def test_the_calibrated_model_driven_by_law_gives_the_calibrations_nrmse(column):
    # an independent check of the two APIs: the fitted law replayed from rest over the
    # history has the RMS error the calibration reports
    m = hsmu.read_measured(column)
    cal = hsmu.calibrate(m["time"], m["deformation"], m["force"], units=m["units"])
    force = hsmu.Law(cal["law"], **cal["model"]).drive(m["deformation"])
    rms = np.sqrt(np.mean((force - m["force"]) ** 2))
    assert rms == pytest.approx(cal["rmsError"], rel=1e-9)
    assert rms / np.sqrt(np.mean(m["force"] ** 2)) == pytest.approx(cal["nrmse"], rel=1e-9)


def test_calibrate_with_units_and_a_law_equals_the_program(cli, tmp_path, column):
    # the history written in mm with a header, calibrated with the bilinear law
    m = hsmu.read_measured(column)
    d_mm = m["deformation"] * 1000.0
    data = tmp_path / "column-mm.csv"
    with open(data, "w") as f:
        f.write("time [s], deformation [mm], force [kN]\n")
        for t, d, F in zip(m["time"], d_mm, m["force"]):
            f.write(f"{t!r}, {d!r}, {F!r}\n")
    override = tmp_path / "override.json"
    override.write_text(json.dumps({"model": {"law": "bilinear"}}))
    out = replay(cli, tmp_path, data, "--method", "calibration", "--config", override)
    expected = json.loads((out / "summary.json").read_text())["calibration"]
    result = hsmu.calibrate(m["time"], d_mm, m["force"], units="s,mm,kN", law="bilinear")
    del result["seconds"], expected["seconds"]
    assert result["law"] == "bilinear" and result["units"]["k0"] == "kN/m"
    for key in ("law", "verdict", "units"):
        del result[key]
    assert_same(result, expected)


def test_identify_ukf_equals_hsmu_replay(cli, tmp_path, column):
    m = hsmu.read_measured(column)
    out = replay(cli, tmp_path, column, "--method", "ukf")
    with open(out / "parameters.csv") as f:
        header = [h.rsplit(" [", 1)[0] for h in f.readline().strip().split(",")]
    table = np.genfromtxt(out / "parameters.csv", delimiter=",", skip_header=1)
    col = {name: table[:, i] for i, name in enumerate(header)}
    summary = json.loads((out / "summary.json").read_text())
    r = hsmu.identify(m["time"], m["deformation"], m["force"], units=m["units"], method="ukf")
    assert r["method"] == summary["method"]
    np.testing.assert_allclose(r["auxiliary_force"], col["auxiliary_force"], rtol=1e-12,
                               atol=1e-12 * np.max(np.abs(col["force"])))
    np.testing.assert_allclose(r["fit_error"], col["fit_error"], rtol=1e-12, atol=1e-15)
    for name in r["parameters"]:
        np.testing.assert_allclose(r["parameters"][name], col[name], rtol=1e-12, atol=1e-15)
        np.testing.assert_allclose(r["stddev"][name], col["stddev " + name], rtol=1e-12,
                                   atol=1e-15)
        assert r["final"][name] == pytest.approx(summary["parameters"][name]["final"], rel=1e-12)
    assert r["final_nrmse"] == pytest.approx(summary["finalNrmse"], rel=1e-12)
    assert r["messages"] == summary["messages"]


@pytest.mark.parametrize("units, words", [
    ("s,yd,kN", "unknown deformation unit 'yd' (expected m, cm, mm, in, ft, rad, mrad, deg)"),
    ("s,m", "--units: expected three units TIME,DEFORMATION,FORCE, e.g. s,mm,kN; found 's,m'"),
    ("s,rad,kN", "deformation in rad needs a moment unit"),
])
def test_bad_units_give_the_programs_message(cli, tmp_path, column, units, words):
    done = cli("replay", "--import", column, "--units", units, "--method", "calibration",
               "--out", tmp_path / "x", check=False)
    assert done.returncode == 1 and words in done.stderr
    with pytest.raises(ValueError) as error:
        hsmu.calibrate([0.0, 1.0, 2.0], [0.0, 1.0, 0.0], [0.0, 1.0, 0.0], units=units)
    assert words in str(error.value)
    assert words in done.stderr.split(": ", 1)[1]


def test_bad_arrays():
    t, d, f = np.arange(5.0), np.linspace(0, 1, 5), np.linspace(0, 2, 5)
    with pytest.raises(ValueError, match=r"same length \(5, 4, 5\)"):
        hsmu.calibrate(t, d[:4], f)
    with pytest.raises(ValueError, match="force: value 2 is not finite"):
        hsmu.calibrate(t, d, np.where(np.arange(5) == 2, np.nan, f))
    with pytest.raises(TypeError, match="deformation: expected real numbers"):
        hsmu.calibrate(t, d.astype(complex), f)
    with pytest.raises(ValueError, match="time: expected a 1-D array"):
        hsmu.calibrate(t.reshape(5, 1), d, f)
    with pytest.raises(ValueError, match="does not increase|not increasing|increas"):
        hsmu.calibrate(t[::-1].copy(), d, f)
    with pytest.raises(TypeError, match="units"):
        hsmu.calibrate(t, d, f, units=3)
    with pytest.raises(ValueError, match="ukf|UKF|bilinear"):
        hsmu.identify(t, d, f, method="ukf", law="bilinear")


def test_ctrl_c_stops_a_calibration(column):
    m = hsmu.read_measured(column)
    phases = []

    def progress(p):
        phases.append(p["phase"])
        os.kill(os.getpid(), signal.SIGINT)  # Ctrl+C while the calibration runs

    with pytest.raises(KeyboardInterrupt):
        hsmu.calibrate(m["time"], m["deformation"], m["force"], units=m["units"],
                       progress=progress)
    # stopped inside the calibration (it reports "minimization i of N" as it goes): never "done"
    assert phases and set(phases) == {"calibration"}


def test_documented():
    for name in ("calibrate", "identify", "identify_record", "read_measured"):
        assert "hsmu replay" in getattr(hsmu, name).__doc__


def test_identify_record_equals_hsmu_replay_identify(cli, tmp_path):
    cli("run", "paper-condition-3", "--out", tmp_path / "run", cwd=tmp_path)
    record = tmp_path / "run" / "record.h5"
    cli("replay", record, "--identify", "--out", tmp_path / "replay")
    with open(tmp_path / "replay" / "parameters.csv") as f:
        header = [h.rsplit(" [", 1)[0] for h in f.readline().strip().split(",")]
    table = np.genfromtxt(tmp_path / "replay" / "parameters.csv", delimiter=",", skip_header=1)
    summary = json.loads((tmp_path / "replay" / "summary.json").read_text())
    r = hsmu.identify_record(record)
    assert r["method"] == summary["method"] == "UKF"
    assert r["units"]["deformation"] == summary["units"]["deformation"] == "rad"
    arrays = {"time": r["time"], "deformation": r["deformation"], "force": r["force"],
              "auxiliary_force": r["auxiliary_force"], "fit_error": r["fit_error"]}
    arrays.update(r["parameters"])
    arrays.update({"stddev " + k: v for k, v in r["stddev"].items()})
    assert sorted(arrays) == sorted(header)
    for j, name in enumerate(header):
        np.testing.assert_allclose(arrays[name], table[:, j], rtol=1e-12, atol=1e-300,
                                   err_msg=name)
    assert r["final_nrmse"] == pytest.approx(summary["finalNrmse"], rel=1e-12)
    assert r["calibration"]["nrmse"] == pytest.approx(summary["calibration"]["nrmse"], rel=1e-12)
    with pytest.raises(ValueError):
        hsmu.identify_record(record, specimen="no such element")


def synthetic_with_offsets():
    """The specimen of test_identification_calibrationoffsets: a Bouc-Wen law (m, kN) along 6
    growing cycles, measured with a deformation offset of 3 mm and a force offset of 5 % of its
    peak force (the plain law's force along the true deformation, plus the offset)."""
    k = np.arange(1, 6 * 400 + 1)
    c = k / 400.0
    u_true = 0.05 * c / 6 * np.sin(2 * np.pi * c)
    law = hsmu.Law("boucWen", k0=1.5, alpha=0.05, n=2.0, beta=0.6, gamma=0.2, deltaNu=0.002,
                   deltaEta=0.002, uRef=0.01, fRef=100.0)
    f_true = law.drive(u_true)
    u0, f0 = 0.003, 0.05 * np.max(np.abs(f_true))
    return 0.01 * k, u_true + u0, f_true + f0, u0, f0


def test_calibrate_offsets_recovers_known_offsets_with_intervals():
    t, u, f, u0, f0 = synthetic_with_offsets()
    cal = hsmu.calibrate(t, u * 1000, f, units="s,mm,kN")  # offsets "auto", as the command
    off = cal["offsets"]
    assert off["used"] and off["criterion"] < 0 and off["nrmseWith"] < off["nrmseWithout"]
    d, F = off["deformationOffset"], off["forceOffset"]
    assert d["value"] == pytest.approx(u0, rel=0.01)  # in m: the console's units
    assert F["value"] == pytest.approx(f0, rel=0.01)
    assert (d["unit"], F["unit"]) == ("m", "kN")
    for p in (d, F):
        lo, hi = p["ci95"]
        assert lo < p["value"] < hi and hi - lo == pytest.approx(2 * 1.96 * p["stddev"])
    assert cal["parameters"]["forceOffset"]["value"] == F["value"]
    assert cal["model"]["forceOffset"] == F["value"]
    on = hsmu.calibrate(t, u, f, offsets="on")
    assert on["offsets"]["used"] and "forceOffset" in on["model"]


def test_calibrate_offsets_off_and_a_bad_value():
    t, u, f, _, _ = synthetic_with_offsets()
    off = hsmu.calibrate(t, u, f, offsets="off")
    assert "offsets" not in off
    assert "forceOffset" not in off["model"] and "forceOffset" not in off["parameters"]
    with pytest.raises(ValueError, match="offsets: expected auto, on or off, found 'sometimes'"):
        hsmu.calibrate(t, u, f, offsets="sometimes")
