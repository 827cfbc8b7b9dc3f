"""examples/python/cloth_sweep_dask.py on a 2-worker Dask LocalCluster, reached at its scheduler's
TCP address as a real cluster would be: its table holds, bit for bit, the numbers of the same
runs done one after another in this process."""
import csv
import importlib.util
import os
import subprocess
import sys

import pytest

distributed = pytest.importorskip("distributed", reason="Dask is Debian's python3-distributed")

FRAMES = 8


def load_example(source_dir):
    path = source_dir.resolve() / "examples" / "python" / "cloth_sweep_dask.py"
    spec = importlib.util.spec_from_file_location("cloth_sweep_dask", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return path, module


def test_the_sweep_on_a_cluster_equals_the_serial_runs(source_dir, tmp_path):
    script, example = load_example(source_dir)
    path = os.pathsep.join(os.path.abspath(p) for p in sys.path if p)
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=path)
    # The workers are processes of their own: they find animkit through PYTHONPATH, as workers
    # on other machines would through their own installation.
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, env={"PYTHONPATH": path}) as cluster:
        result = subprocess.run(
            [sys.executable, str(script), "--scheduler", cluster.scheduler_address, "--out",
             str(tmp_path / "sweep"), "--frames", str(FRAMES)],
            env=env, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("9 runs: ")
    assert (tmp_path / "sweep" / "sweep.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with open(tmp_path / "sweep" / "sweep.csv", newline="") as table:
        rows = list(csv.DictReader(table))

    serial = example.sweep_serially(frames=FRAMES)
    assert len(rows) == len(serial) == 9
    for row, expected in zip(rows, serial):
        for key, value in expected.items():
            if key == "seconds":
                continue
            # Python writes a float's shortest repr, which reads back to the same bits.
            assert float(row[key]) == value, (key, row, expected)
