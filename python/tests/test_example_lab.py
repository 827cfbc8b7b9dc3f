"""examples/python/lab_drawings.py reproduces the lab: it runs as a script, prints the table of
the five shapes with both solvers (numbers equal to the library's own summaries) and writes the
plot of iterations per target."""
import os
import pathlib
import subprocess
import sys

import pytest

import animkit

SOLVER_LABELS = {"CCD": "ccd", "FABRIK": "fabrik"}


@pytest.fixture(scope="module")
def script(source_dir):
    path = (pathlib.Path(source_dir) / "examples" / "python" / "lab_drawings.py").resolve()
    assert path.is_file()
    return path


def run_script(script, cwd, *args):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, str(script), *args], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def table_rows(stdout):
    """{(shape, solver): [targets, converged %, mean iter, max iter, jitter, mean error]}."""
    rows = {}
    for line in stdout.splitlines():
        fields = line.split()
        if len(fields) == 8 and fields[1] in SOLVER_LABELS:
            rows[fields[0], SOLVER_LABELS[fields[1]]] = [float(f) for f in fields[2:]]
    return rows


def test_the_example_prints_the_labs_table_and_plots_it(script, tmp_path):
    done = run_script(script, tmp_path, "iterations.png")
    assert done.returncode == 0, done.stderr
    rows = table_rows(done.stdout)
    shapes = animkit.lab_shape_names()
    assert set(rows) == {(shape, solver) for shape in shapes for solver in ("ccd", "fabrik")}
    arm = animkit.Chain.lab_arm()
    for (shape, solver), row in rows.items():
        s = animkit.run_drawing(arm, animkit.lab_shape(shape), solver=solver).summary()
        targets, converged, mean_iter, max_iter, jitter, mean_error = row
        assert targets == s.targets
        assert converged == round(100 * s.converged_fraction, 1) == 100.0
        assert mean_iter == pytest.approx(s.iterations_mean, abs=0.005)
        assert max_iter == s.iterations_max
        assert jitter == pytest.approx(s.max_joint_step_rad, abs=5e-5)
        assert mean_error == pytest.approx(s.error_mean, rel=1e-3)
    # The lab's finding: FABRIK needs fewer iterations per target than CCD on every shape,
    # and CCD turns its joints more smoothly (less jitter).
    for shape in shapes:
        assert rows[shape, "fabrik"][2] < rows[shape, "ccd"][2]
        assert rows[shape, "ccd"][4] < rows[shape, "fabrik"][4]

    png = tmp_path / "iterations.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    pixels = animkit.read_gray_image(png)
    assert pixels.shape == (1000, 1100)
    assert (pixels < 128).mean() > 0.01  # lines, labels and bars, not a blank page
    assert "wrote iterations.png" in done.stdout


def test_the_example_reports_bad_options(script, tmp_path):
    done = run_script(script, tmp_path, "out.png", "--tolerance", "-1")
    assert done.returncode == 2
    assert "error: tolerance must be a positive finite number, got -1" in done.stderr
    assert not (tmp_path / "out.png").exists()
