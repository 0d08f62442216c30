"""hsmu.Record against `hsmu export --csv` of the same record, and bad files."""
import csv
import json
import shutil
from pathlib import Path

import numpy as np
import pytest

import hsmu

TABLES = ("steps", "dofs", "elements", "actuators", "sites", "updating")


@pytest.fixture(scope="module")
def run(cli, tmp_path_factory):
    """paper-condition-3 run by the program, and its record exported as CSV by the program."""
    work = tmp_path_factory.mktemp("record")
    cli("run", "paper-condition-3", "--out", work / "run", cwd=work)
    cli("export", work / "run" / "record.h5", "--csv", work / "csv")
    return work


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def split_header(field):
    """'time [s]' -> ('time', 's'); 'step' -> ('step', '')."""
    if field.endswith("]") and " [" in field:
        name, unit = field[:-1].rsplit(" [", 1)
        return name, unit
    return field, ""


def test_every_exported_column_is_a_dataset_with_its_unit(run):
    rec = hsmu.Record(run / "run" / "record.h5")
    seen = set()
    for table in TABLES:
        header, rows = read_csv(run / "csv" / f"{table}.csv")
        values = np.array([[float(x) for x in row] for row in rows])
        assert len(values) == rec.rows == 3001
        for j, field in enumerate(header):
            name, unit = split_header(field)
            assert name in rec, name
            assert rec.units[name] == unit, name
            np.testing.assert_array_equal(rec[name], values[:, j], err_msg=name)
            seen.add(name)
    assert seen == set(rec.names)  # nothing more, nothing less than the export


def test_logs_metadata_and_configuration(run):
    rec = hsmu.Record(run / "run" / "record.h5")
    header, rows = read_csv(run / "csv" / "alarms.csv")
    assert len(rec.alarms) == len(rows) == 2
    for alarm, row in zip(rec.alarms, rows):
        assert [alarm["time"], alarm["step"],
                alarm["severity"], alarm["kind"], alarm["message"], alarm["code"]] == \
            [float(row[0]), int(row[1]), row[2], row[3], row[4], row[5]]
    header, rows = read_csv(run / "csv" / "update_events.csv")
    assert len(rec.events) == len(rows)
    params = rec.updating["parameters"]
    for event, row in zip(rec.events, rows):
        assert (event["step"], event["time"], event["element"]) == (int(row[0]), float(row[1]),
                                                                    row[2])
        assert [event["values"][p] for p in params] == [float(x) for x in row[3:3 + len(params)]]
    summary = json.loads((run / "run" / "summary.json").read_text())
    config = json.loads((hsmu_source() / "resources/presets/paper-condition-3.json").read_text())
    assert rec.configuration["name"] == config["name"] == rec.metadata["config_name"]
    assert rec.metadata["dt"] == config["analysis"]["dt"]
    assert rec.metadata["program_version"] == hsmu.__version__
    assert rec.updating["specimen"] in [e["name"] for e in rec.elements if e["experimental"]]
    assert rec.swmr and rec.refresh() == 0  # a finished record: nothing new
    assert summary  # the run wrote its summary beside the record
    # how the console reached the site (issue 26): the record and summary.json say the same
    assert rec.site_security == summary["link_security"] == {"controller": "builtin"}


def hsmu_source():
    import os
    import pathlib
    return pathlib.Path(os.environ["HSMU_SOURCE_DIR"])


def test_unknown_dataset(run):
    rec = hsmu.Record(run / "run" / "record.h5")
    with pytest.raises(KeyError, match="no dataset 'nothing'"):
        rec["nothing"]


@pytest.mark.parametrize("damage", ["missing", "text", "truncated"])
def test_bad_files_raise_oserror_with_the_programs_message(cli, run, tmp_path, damage):
    path = tmp_path / f"{damage}.h5"
    if damage == "text":
        path.write_text("time,force\n0,1\n")
    elif damage == "truncated":
        data = (run / "run" / "record.h5").read_bytes()
        path.write_bytes(data[: len(data) // 3])
    done = cli("export", path, "--csv", tmp_path / "csv", check=False)
    assert done.returncode != 0
    with pytest.raises(OSError) as error:
        hsmu.Record(path)
    assert str(error.value) in done.stderr
    assert str(path) in str(error.value)


@pytest.mark.parametrize("layout", ["row chunks (older)", "2-D chunks"])
def test_records_of_either_chunk_layout_read_as_their_export(cli, tmp_path, layout):
    """A wide record (300 DOFs and elements) in the older whole-row-chunk layout (the committed
    fixture, written before issue 27's 2-D chunks) and one written now by the program: every
    exported column equals hsmu.Record's (docs/recording.md "Chunks")."""
    if layout.startswith("row"):
        path = Path(__file__).resolve().parents[1] / "core/record/fixtures/record-row-chunks-300.h5"
    else:
        cli("run", "shear-building-300", "--duration", "0.003", "--csv", "none",
            "--out", tmp_path / "run", cwd=tmp_path)
        path = tmp_path / "run" / "record.h5"
    cli("export", path, "--csv", tmp_path / "csv")
    rec = hsmu.Record(path)
    assert rec.rows == 4
    for table in ("dofs", "elements"):
        header, rows = read_csv(tmp_path / "csv" / f"{table}.csv")
        values = np.array([[float(x) for x in row] for row in rows])
        assert values.shape == (4, 2 + 3 * 300)
        for j, field in enumerate(header):
            name, _ = split_header(field)
            np.testing.assert_array_equal(rec[name], values[:, j], err_msg=name)


def test_chosen_and_decimated_dofs_read_as_their_export(cli, tmp_path):
    """A record of DOF 2 every 4 steps (hsmu run --record-dofs / --record-every, issue 27):
    its DOF datasets hold the kept rows with their true steps, equal to the full record's
    rows; every other dataset equals the full record's; a DOF not kept is a KeyError naming
    it and the option."""
    common = ("--duration", "2", "--csv", "none")
    cli("run", "paper-condition-3", "--out", tmp_path / "full", *common)
    cli("run", "paper-condition-3", "--out", tmp_path / "chosen", *common,
        "--record-dofs", "DOF 2", "--record-every", "4")
    cli("export", tmp_path / "chosen" / "record.h5", "--csv", tmp_path / "csv")
    full = hsmu.Record(tmp_path / "full" / "record.h5")
    rec = hsmu.Record(tmp_path / "chosen" / "record.h5")
    assert rec.dofs == full.dofs == ["DOF 1", "DOF 2"]
    assert rec.recorded_dofs == ["DOF 2"] and rec.record_every == 4
    assert full.recorded_dofs == full.dofs and full.record_every == 1
    np.testing.assert_array_equal(full.dof_steps, full["step"])
    np.testing.assert_array_equal(rec.dof_steps, np.arange(0, 201, 4))
    np.testing.assert_array_equal(rec.dof_time, full["time"][::4])
    for kind in ("u", "v", "a"):
        np.testing.assert_array_equal(rec[f"{kind} DOF 2"], full[f"{kind} DOF 2"][::4])
        with pytest.raises(KeyError, match=r"DOF 'DOF 1' \(index 0\) was not recorded.*"
                                           r"--record-dofs"):
            rec[f"{kind} DOF 1"]
    for name in rec.names:  # the specimens, elements, updating: complete, every step
        if not name.startswith(("u ", "v ", "a ")) and "round trip" not in name:
            np.testing.assert_array_equal(rec[name], full[name], err_msg=name)
    header, rows = read_csv(tmp_path / "csv" / "dofs.csv")
    assert header == ["step", "time [s]", "u DOF 2 [m]", "v DOF 2 [m/s]", "a DOF 2 [m/s^2]"]
    values = np.array([[float(x) for x in row] for row in rows])
    np.testing.assert_array_equal(values[:, 0], rec.dof_steps)
    np.testing.assert_array_equal(values[:, 2], rec["u DOF 2"])
    summary = json.loads((tmp_path / "chosen" / "summary.json").read_text())
    assert summary["record_dofs"] == {"dofs": "1", "recorded": 1, "of": 2, "every": 4}
    assert "record_dofs" not in json.loads((tmp_path / "full" / "summary.json").read_text())
