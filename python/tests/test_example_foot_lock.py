"""examples/python/foot_lock_walk.py runs on the CMU walk and draws its plot."""
import re
import subprocess
import sys

import numpy as np
import pytest

import animkit


@pytest.fixture(scope="module")
def script(source_dir):
    return source_dir / "examples" / "python" / "foot_lock_walk.py"


def run(script, *args, cwd):
    return subprocess.run([sys.executable, str(script), *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=300)


def test_plots_the_walk(script, tmp_path):
    # No path given: the script finds the repository's walk next to itself.
    done = run(script, "--out", tmp_path / "walk.png", "--fixed", tmp_path / "fixed.bvh",
               cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    numbers = re.search(r"994 frames, contacts left (\d+) right (\d+), sliding ([\d.]+) -> "
                        r"([\d.]+) cm/frame", done.stdout)
    assert numbers, done.stdout
    left, right, before, after = numbers.groups()
    assert int(left) > 0 and int(right) > 0
    assert float(after) < float(before)

    png = tmp_path / "walk.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    import matplotlib.image
    image = matplotlib.image.imread(png)
    assert image.shape[:2] == (700, 1200)
    # Both line colours are drawn: matplotlib's orange (before) and blue (after).
    rgb = (image[:, :, :3] * 255).round().astype(int).reshape(-1, 3)
    for colour in [(255, 127, 14), (31, 119, 180)]:
        assert (np.abs(rgb - colour).sum(axis=1) <= 6).sum() > 500, colour

    fixed = animkit.read_bvh(tmp_path / "fixed.bvh")
    assert fixed.frame_count == 994


def test_bad_file_is_reported(script, tmp_path):
    bad = tmp_path / "bad.bvh"
    bad.write_text("HIERARCHY\nROOT Hips\n{\n")
    done = run(script, bad, "--out", tmp_path / "x.png", cwd=tmp_path)
    assert done.returncode == 2
    assert done.stderr.startswith("foot_lock_walk: ") and "bad.bvh" in done.stderr
    assert not (tmp_path / "x.png").exists()
