# The package under test is the build tree's (PYTHONPATH=<build>/python, set by ctest), the
# command the same build's bimrock (BIMROCK_BINARY), the examples the source tree's.
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("BIMROCK_SOURCE_DIR",
                                         pathlib.Path(__file__).resolve().parents[2]))
BINARY = os.environ.get("BIMROCK_BINARY", str(SOURCE_DIR / "build" / "release" / "bimrock"))


def example(*parts):
    return SOURCE_DIR.joinpath("examples", *parts)


def run_command(case_file, out):
    """`bimrock run CASE -o OUT -q`: the command's results folder for the same case."""
    done = subprocess.run([BINARY, "run", str(case_file), "-o", str(out), "-q"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return pathlib.Path(out)


@pytest.fixture(scope="module")  # once per test file: the run takes a fraction of a second
def pull_out_command(tmp_path_factory):
    return run_command(example("pull_out", "case.yaml"), tmp_path_factory.mktemp("cmd") / "pull_out")
