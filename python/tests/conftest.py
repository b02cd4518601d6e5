"""Shared fixtures: the CLI built beside the module (ctest passes CB_CLI_PATH) and the source tree."""
import os
import pathlib
import subprocess

import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("CB_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture
def cli():
    """Runs the contactbench program with the given arguments; fails the test on a non-zero exit."""
    path = os.environ.get("CB_CLI_PATH")
    if not path:
        pytest.skip("CB_CLI_PATH is not set (ctest sets it to the contactbench program of the build)")

    def run(*args):
        done = subprocess.run([path, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout

    return run


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture(scope="session")
def make_stubs():
    """python/make_stubs.py as a module, loaded by its path: putting python/ on sys.path would shadow the
    package under test with its sources."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("make_stubs", SOURCE_DIR / "python" / "make_stubs.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
