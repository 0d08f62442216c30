"""hsmu.run against a real actuator controller: a `hsmu-controller` process over TCP, as
`hsmu run --controller tcp://HOST:PORT` runs it (docs/python.md "Runs against a
controller"); the token from a 0600 file or HSMU_CONTROLLER_TOKEN (docs/security.md).
Each run gets a controller of its own (a controller keeps its specimen's damage between
sessions)."""
import json
import os
import re
import subprocess
import threading

import numpy as np
import pytest

import hsmu

PRESET = "paper-condition-3"
HELD = re.compile(r"hsmu run: test held at t = (\S+) s \(step (\d+)\): (.*)")
LOST = re.compile(r"^(.*: no measurement for step \d+: )"
                  r"(the controller closed the connection|connection lost: .+)$")
# When the kill lands between two steps the link notices first and the next step finds it down;
# the reason in brackets is the link's own (LinkClient::closeReason, never empty).
DOWN = re.compile(r"^(Element 1: link to \S+) is down "
                  r"\((the controller closed the connection|connection lost: .+)\); "
                  r"resume to reconnect$")


@pytest.fixture
def config_file(tmp_path):
    """paper-condition-3 shortened to 10 s (1001 rows), as a file both runs read."""
    config = hsmu.load_config(PRESET)
    config["analysis"]["duration"] = 10.0
    path = tmp_path / "short.json"
    path.write_text(json.dumps(config))
    return path


def test_steps_equal_hsmu_run_against_a_controller(cli, controllers, config_file, token_file,
                                                   tmp_path, monkeypatch):
    theirs = controllers(PRESET, token_file=token_file)
    cli("run", config_file, "--controller", theirs.address, "--token-file", token_file,
        "--out", tmp_path / "cli")
    ours = controllers(PRESET, token_file=token_file)
    result = hsmu.run(config_file, controller=ours.address, token_file=token_file,
                      out=tmp_path / "py")
    assert result["status"] == "finished" and result["hold_reason"] is None
    rec = hsmu.Record(tmp_path / "cli" / "record.h5")
    steps = result["steps"]
    assert rec.rows == len(steps["time_s"]) == 1001
    pairs = {"time_s": "time", "ag_m_s2": "ground_acceleration", "DOF 1_u_m": "u DOF 1",
             "DOF 2_v_m_s": "v DOF 2", "DOF 2_a_m_s2": "a DOF 2",
             "Element 1_deformation_rad": "Element 1 deformation",
             "Element 1_force_kNm": "Element 1 force", "Element 1_commanded_rad":
             "Element 1 commanded", "Element 3_force_kN": "Element 3 force",
             "param_k0": "k0", "aux_force_kNm": "auxiliary_force", "fit_error": "fit_error"}
    for array, dataset in pairs.items():
        np.testing.assert_allclose(steps[array], rec[dataset], rtol=1e-12, atol=0,
                                   err_msg=array)
    # the files too: steps.csv to the letter, the summaries but for the wall time
    assert (tmp_path / "py" / "steps.csv").read_text() == \
        (tmp_path / "cli" / "steps.csv").read_text()
    a = json.loads((tmp_path / "py" / "summary.json").read_text())
    b = json.loads((tmp_path / "cli" / "summary.json").read_text())
    for s in (a, b):
        del s["wall_time_s"]
    assert a == b
    # the link's security, in the result, summary.json and the record (docs/security.md)
    assert result["summary"]["link_security"] == {"controller": "plaintext-loopback"}
    assert hsmu.Record(tmp_path / "py" / "record.h5").site_security == \
        {"controller": "plaintext-loopback"}

    # the token from the environment, as `hsmu run` takes it without --token-file
    again = controllers(PRESET, token_file=token_file)
    monkeypatch.setenv("HSMU_CONTROLLER_TOKEN", token_file.read_text().strip())
    from_env = hsmu.run(config_file, controller=again.address)
    np.testing.assert_array_equal(from_env["steps"]["DOF 1_u_m"], steps["DOF 1_u_m"])


def test_a_wrong_token_is_the_programs_error(cli, controllers, config_file, token_file,
                                             tmp_path):
    wrong = tmp_path / "wrong.token"
    fd = os.open(wrong, os.O_WRONLY | os.O_CREAT, 0o600)
    os.write(fd, b"not-the-secret\n")
    os.close(fd)
    theirs = controllers(PRESET, token_file=token_file)
    done = cli("run", config_file, "--controller", theirs.address, "--token-file", wrong,
               "--out", tmp_path / "cli", check=False)
    assert done.returncode == 1
    ours = controllers(PRESET, token_file=token_file)
    with pytest.raises(ValueError) as error:
        hsmu.run(config_file, controller=ours.address, token_file=wrong)
    message = str(error.value).replace(ours.address[6:], theirs.address[6:])
    assert "hsmu run: " + message in done.stderr
    assert "token" in message
    # an unreadable-by-others rule and a bad address, as the program says them
    os.chmod(wrong, 0o644)
    with pytest.raises(ValueError, match="chmod 600"):
        hsmu.run(config_file, controller=ours.address, token_file=wrong)
    with pytest.raises(ValueError, match="controller: "):
        hsmu.run(config_file, controller="tcp://nowhere")


def test_a_dropped_controller_holds_with_the_programs_reason(cli, controllers, token_file,
                                                             tmp_path):
    """The controller killed (SIGKILL, no goodbye) while the console waits for a measurement:
    each reply leaves 150 ms after its target (--reply-delay), so a kill made once a step is
    committed lands in the next step's wait, for `hsmu run` and hsmu.run alike."""
    config = hsmu.load_config(PRESET)
    config["analysis"]["duration"] = 0.6  # 60 steps
    path = tmp_path / "short.json"
    path.write_text(json.dumps(config))
    slow = dict(pace="fast", token_file=token_file, extra=("--reply-delay", "150"))

    theirs = controllers(PRESET, **slow)
    run = subprocess.Popen(
        [os.environ["HSMU_CLI"], "run", str(path), "--controller", theirs.address,
         "--token-file", str(token_file), "--out", str(tmp_path / "cli")],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
    err = []
    for line in run.stderr:  # progress every 5 %: 3 steps
        err.append(line)
        if " 10 %" in line:
            theirs.kill()
            break
    out, rest = run.communicate()
    err = "".join(err) + rest
    assert run.returncode == 2, err  # held
    held = HELD.search(err)
    assert held, err
    cli_step, cli_reason = int(held.group(2)), held.group(3)

    ours = controllers(PRESET, **slow)
    committed = threading.Event()

    def kill_when_committed():
        committed.wait()
        ours.kill()

    killer = threading.Thread(target=kill_when_committed)
    killer.start()

    def progress(p):  # every step (60 < 100)
        if p["step"] == cli_step:
            committed.set()

    try:
        result = hsmu.run(path, controller=ours.address, token_file=token_file,
                          out=tmp_path / "py", progress=progress)
    finally:
        committed.set()
        killer.join()
    assert result["status"] == "held" and not result["interrupted"]
    # The same sentence: "<element>: link to <address>: no measurement for step N: <how the
    # link went>". How it went is the kernel's: a FIN ("the controller closed the connection")
    # or, when the killed controller had unread bytes (a heartbeat), an RST ("connection lost:
    # Connection reset by peer"), whichever front end runs.
    ours_said, theirs_said = LOST.match(result["hold_reason"]), LOST.match(cli_reason)
    if ours_said and theirs_said:
        assert ours_said.group(1) == theirs_said.group(1).replace(theirs.address, ours.address)
        assert theirs_said.group(1).startswith(f"Element 1: link to {theirs.address}: ")
    else:  # one of them found the link already down: both name the element and its link
        for reason, address in ((result["hold_reason"], ours.address), (cli_reason, theirs.address)):
            said = LOST.match(reason) or DOWN.match(reason)
            assert said and reason.startswith(f"Element 1: link to {address}"), \
                (result["hold_reason"], cli_reason)
    # the same steps kept, in the record and the summary, as `hsmu run` keeps them
    n = len(result["steps"]["time_s"])
    assert n == cli_step + 1
    assert hsmu.Record(tmp_path / "py" / "record.h5").rows == n == \
        hsmu.Record(tmp_path / "cli" / "record.h5").rows
    ours_summary = json.loads((tmp_path / "py" / "summary.json").read_text())
    theirs_summary = json.loads((tmp_path / "cli" / "summary.json").read_text())
    assert ours_summary["steps"] == theirs_summary["steps"] == result["summary"]["steps"]
    assert ours_summary["state"] == theirs_summary["state"]
