# The build tree's package (PYTHONPATH=build/python, set by ctest) and the
# CLI beside it (STOCHTEX_CLI), which some tests compare against.
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("STOCHTEX_CLI")
    if not path or not os.path.exists(path):
        pytest.fail("STOCHTEX_CLI must name the stochtex command (ctest sets it)")

    def run(*args, check=True):
        return subprocess.run([path, *args], capture_output=True, text=True, check=check)

    return run
