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
