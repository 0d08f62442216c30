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
