"""Fixtures of the hsmu module's tests: the `hsmu` program to compare with, the shared data."""
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    """Run `hsmu ARGS...`; returns the CompletedProcess (text, captured)."""
    path = os.environ.get("HSMU_CLI")
    if not path or not os.path.exists(path):
        raise RuntimeError("HSMU_CLI must name the hsmu program (CTest sets it)")

    def run(*args, check=True, cwd=None):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True, cwd=cwd,
                              env={**os.environ, "QT_QPA_PLATFORM": "offscreen"})
        if check and done.returncode != 0:
            raise AssertionError(f"hsmu {' '.join(map(str, args))} exited {done.returncode}:\n"
                                 f"{done.stderr}")
        return done

    return run


@pytest.fixture(scope="session")
def shared_data():
    """The shared real records folder; the test is skipped with a reason when it is absent."""
    path = pathlib.Path(os.environ.get("HSMU_SHARED_DATA_DIR", ""))
    if not path.is_dir():
        pytest.skip(f"shared data absent ({path}): the real-record comparison needs it")
    return path


def write_column(path, values):
    """A one-column history file with every value exact (repr round-trips float64)."""
    with open(path, "w") as f:
        f.write("deformation\n")
        for v in values:
            f.write(repr(float(v)) + "\n")


class Controller:
    """A real `hsmu-controller` process (HSMU_CONTROLLER) on a free loopback port, serving the
    experimental elements of `config`; port and address known once it says it listens."""

    def __init__(self, config, pace, token_file=None, extra=()):
        path = os.environ.get("HSMU_CONTROLLER")
        if not path or not os.path.exists(path):
            raise RuntimeError("HSMU_CONTROLLER must name hsmu-controller (CTest sets it)")
        args = [path, "--config", str(config), "--port", "0", "--pace", pace, "--no-state-file",
                "--quiet"]
        if token_file:
            args += ["--token-file", str(token_file)]
        args += list(extra)
        env = {k: v for k, v in os.environ.items() if k != "HSMU_CONTROLLER_TOKEN"}
        self.process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                        text=True, env=env)
        line = self.process.stdout.readline()  # "hsmu-controller: listening on HOST:PORT (...)"
        if "listening on" not in line:
            self.stop()
            raise AssertionError(f"hsmu-controller did not start: {line}{self.process.stderr.read()}")
        self.port = int(line.split("listening on ")[1].split()[0].rsplit(":", 1)[1])
        self.address = f"tcp://127.0.0.1:{self.port}"

    def kill(self):
        """SIGKILL: the link drops with no goodbye."""
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()

    def stop(self):
        if self.process.poll() is None:
            self.process.terminate()
        self.process.communicate()


@pytest.fixture
def controllers():
    """Start controllers with controllers(config, pace, token_file=None, extra=()); all
    stopped at the end."""
    started = []

    def start(config, pace="fast", token_file=None, extra=()):
        c = Controller(config, pace, token_file, extra)
        started.append(c)
        return c

    yield start
    for c in started:
        c.stop()


@pytest.fixture
def token_file(tmp_path):
    """A controller token in a file only its owner can read (docs/security.md)."""
    path = tmp_path / "lab.token"
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    os.write(fd, b"py-lab-secret-5e1d\n")
    os.close(fd)
    return path
