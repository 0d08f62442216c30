"""The module itself: imported from the build tree, its version that of the program."""
import os

import hsmu


def test_imported_from_the_build_tree():
    assert os.path.dirname(hsmu.__file__) == os.path.abspath(os.environ["PYTHONPATH"].split(":")[0])


def test_version_is_the_programs(cli):
    out = cli("--version").stdout
    assert hsmu.__version__ and hsmu.__version__ in out


def test_documented():
    assert hsmu.__doc__
    for name in ("Law", "laws"):
        assert getattr(hsmu, name).__doc__, name
