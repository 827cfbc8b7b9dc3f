"""Shared fixtures: where the CLI, the data and the source tree are (ctest sets them; see
python/tests/CMakeLists.txt), and a check that the animkit imported is the one just built."""
import os
import pathlib

import pytest


def _path_from_env(name):
    value = os.environ.get(name)
    if not value:
        pytest.skip(f"{name} is not set (run the tests through ctest or make test)")
    return pathlib.Path(value)


@pytest.fixture(scope="session")
def cli():
    """The animkit command-line tool built with the module."""
    return _path_from_env("ANIMKIT_CLI")


@pytest.fixture(scope="session")
def data_dir():
    """The repository's data/ folder (the CMU walk: cmu/131_01.bvh)."""
    return _path_from_env("ANIMKIT_DATA_DIR")


@pytest.fixture(scope="session")
def source_dir():
    """The repository's root (examples/, docs/scenes/)."""
    return _path_from_env("ANIMKIT_SOURCE_DIR")
