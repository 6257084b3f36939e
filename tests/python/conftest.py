"""Shared fixtures: the source tree, the CLI beside the package, scenes loaded once."""
import os
import subprocess
from pathlib import Path

import pytest

import rollspin

SOURCE_DIR = Path(os.environ.get("ROLLSPIN_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SCENES = SOURCE_DIR / "scenes"
CLI = os.environ.get("ROLLSPIN_BINARY", str(SOURCE_DIR / "build" / "rollspin"))


def run_cli(*args, cwd=None):
    """The CLI's stdout; fails the test with its stderr when it exits non-zero."""
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    assert done.returncode == 0, done.stderr
    return done.stdout


@pytest.fixture(scope="session")
def lollipop():
    return rollspin.load(SCENES / "lollipop.toml")
