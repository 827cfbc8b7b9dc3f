"""Shared fixtures: where the CLI, the data and the source tree are (ctest sets them; see
python/tests/CMakeLists.txt), a check that the animkit imported is the one just built, and
run_watched, the threads tests' deterministic proof that a call releases the GIL."""
import os
import pathlib
import sys
import threading
import time

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


def _run_watched(work, each_turn=None):
    """Runs work() in a worker thread while this thread counts the turns it gets before work()
    returns; returns (turns, work's result, [each_turn()'s results]).

    The switch interval is 100 s meanwhile, so the interpreter never takes the GIL from a
    thread: it changes hands only when a thread lets go of it. This thread gets a turn only
    when work() lets go; work() holding the GIL from start to end leaves it none (the worker
    finishes before this thread runs again). turns > 0 thus proves that something work()
    called released the GIL while it ran: make work() call only what is under test (in a loop,
    so that one release is long enough for this thread to wake). Each turn calls each_turn(),
    if given, then sleeps 0.1 ms: the sleep lets go of the GIL so the worker goes on."""
    finished = threading.Event()
    result, errors = [], []

    def run():
        try:
            result.append(work())
        except BaseException as error:  # pragma: no cover (re-raised below)
            errors.append(error)
        finally:
            finished.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(100.0)
    turns, outcomes = 0, []
    try:
        worker = threading.Thread(target=run)
        worker.start()  # returns once the worker runs; it then holds the GIL until it lets go
        while not finished.is_set():
            turns += 1
            if each_turn is not None:
                outcomes.append(each_turn())
            time.sleep(1e-4)
        worker.join()
    finally:
        sys.setswitchinterval(interval)
    if errors:
        raise errors[0]
    return turns, result[0], outcomes


@pytest.fixture
def run_watched():
    """_run_watched: run work() in another thread and count this thread's turns while it
    runs, a deterministic test that work() releases the GIL (no clocks)."""
    return _run_watched
