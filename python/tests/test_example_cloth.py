"""examples/python/cloth_energy.py runs and writes its plot."""
import os
import subprocess
import sys

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def run_example(source_dir, cwd, *args, check=True):
    """The example run by this interpreter in `cwd`, finding the same animkit."""
    script = source_dir.resolve() / "examples" / "python" / "cloth_energy.py"
    path = os.pathsep.join(os.path.abspath(p) for p in sys.path if p)
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONPATH=path)
    return subprocess.run([sys.executable, str(script), *args], cwd=cwd, env=env,
                          capture_output=True, text=True, check=check)


def test_cloth_energy_writes_its_plot_in_the_working_folder(source_dir, tmp_path):
    result = run_example(source_dir, tmp_path, "--frames", "60")
    plot = tmp_path / "cloth_energy.png"
    assert plot.read_bytes()[:8] == PNG_SIGNATURE
    assert plot.stat().st_size > 10_000  # four curves, axes and a legend, not an empty figure
    assert result.stdout.startswith("wrote cloth_energy.png: total energy ")


def test_cloth_energy_takes_a_path_and_a_scene(source_dir, tmp_path):
    out = tmp_path / "plots" / "drape.png"
    out.parent.mkdir()
    run_example(source_dir, tmp_path, str(out), "--scene", "drape-sphere", "--frames", "3")
    assert out.read_bytes()[:8] == PNG_SIGNATURE


def test_cloth_energy_refuses_an_unknown_scene(source_dir, tmp_path):
    result = run_example(source_dir, tmp_path, "--scene", "nope", check=False)
    assert result.returncode != 0
    assert "unknown scene 'nope'" in result.stderr
    assert not (tmp_path / "cloth_energy.png").exists()
