# Fixtures of the Python module's tests (tests/python/CMakeLists.txt sets the environment):
# PYTHONPATH holds the built module, LIMBER the built `limber` command, LIMBER_SOURCE_DIR the
# checkout (its cases).
import json
import os
import pathlib
import subprocess

import pytest


@pytest.fixture(scope="session")
def cases():
    return pathlib.Path(os.environ["LIMBER_SOURCE_DIR"]) / "cases"


@pytest.fixture(scope="session")
def limber_cli():
    """Runs the `limber` command with arguments; returns its --json record."""
    def run(*arguments):
        done = subprocess.run([os.environ["LIMBER"], *map(str, arguments), "--json"],
                              capture_output=True, text=True)
        # 0 ok, 5 ok_inaccurate: both leave a finished file.
        assert done.returncode in (0, 5), done.stderr
        return json.loads(done.stdout)
    return run
