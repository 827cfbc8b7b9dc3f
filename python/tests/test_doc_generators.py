"""The generated pages of the documentation site: the Python API page is written from the
module's own docstrings and refuses a public name without one; the performance page turns
Google Benchmark's JSON into tables that say when, where and at which commit."""
import json
import subprocess
import sys

import animkit


def run(source_dir, script, *args):
    return subprocess.run([sys.executable, str(source_dir / script), *map(str, args)],
                          capture_output=True, text=True)


def test_the_api_page_holds_every_public_name_with_its_docstring(source_dir, tmp_path):
    sys.path.insert(0, str(source_dir / "python" / "tools"))
    import generate_api_page

    text, missing = generate_api_page.build_page(animkit)
    assert missing == []
    for name in animkit.__all__:
        assert f"`{name}`" in text, name
    # A method's signature and the first words of its docstring, as help() shows them.
    assert "global_positions(self: Motion, skeleton: animkit.Skeleton)" in text
    assert animkit.Motion.global_positions.__doc__.splitlines()[2][:40] in text


def test_a_public_name_without_a_docstring_fails_the_page(source_dir, tmp_path):
    package = tmp_path / "fake" / "animkit"
    package.mkdir(parents=True)
    (package / "__init__.py").write_text(
        '__version__ = "1"\n'
        'def documented(x):\n    """Says what it does."""\n'
        'def bare(x):\n    return x\n'
        'class Thing:\n    """A thing."""\n    def undocumented(self):\n        pass\n')
    page = tmp_path / "page.md"
    result = run(source_dir, "python/tools/generate_api_page.py", tmp_path / "fake", page)
    assert result.returncode == 1
    assert "animkit.bare" in result.stderr
    assert "animkit.Thing.undocumented" in result.stderr
    assert "animkit.documented" not in result.stderr
    assert not page.exists()  # whole or absent


def benchmark_json(commit):
    return {
        "context": {"date": "2026-11-28T10:00:00+00:00", "host_name": "vm", "num_cpus": 2,
                    "mhz_per_cpu": 2596, "load_avg": [0.5, 0.25, 0.1], "commit": commit,
                    "animkit_build": "Release", "library_build_type": "debug"},
        "benchmarks": [
            {"name": "BM_Step_mean", "run_name": "BM_Step", "run_type": "aggregate",
             "aggregate_name": "mean", "repetitions": 3, "iterations": 3, "real_time": 9.0,
             "cpu_time": 9.0, "time_unit": "ms", "newton": 4.0},
            {"name": "BM_Step_median", "run_name": "BM_Step", "run_type": "aggregate",
             "aggregate_name": "median", "repetitions": 3, "iterations": 3, "real_time": 7.5,
             "cpu_time": 7.25, "time_unit": "ms", "newton": 3.0},
            {"name": "BM_Once", "run_name": "BM_Once", "run_type": "iteration",
             "repetitions": 1, "iterations": 1, "real_time": 1234.5, "cpu_time": 1200.0,
             "time_unit": "ms"},
        ],
    }


def test_the_performance_page_shows_medians_with_machine_and_commit(source_dir, tmp_path):
    results = tmp_path / "results"
    results.mkdir()
    (results / "cloth_bench.json").write_text(json.dumps(benchmark_json("abc1234")))
    page = tmp_path / "performance.md"
    result = run(source_dir, "scripts/performance-page.py", results, page)
    assert result.returncode == 0, result.stderr
    text = page.read_text()
    assert "## cloth_bench" in text
    assert "animkit commit `abc1234`, Release build" in text
    assert "2 CPUs at 2596 MHz, load average 0.50, 0.25, 0.10" in text
    assert "| `BM_Step` | 3 | 7.5 ms | 7.25 ms | 3 |" in text  # the median, not the mean
    assert "| `BM_Once` | 1 | 1,234 ms | 1,200 ms |  |" in text
    # The program's own description, from bench/cloth_bench.cpp's opening comment.
    assert "Cost of one implicit Euler step" in text


def test_the_performance_page_refuses_what_is_not_benchmark_output(source_dir, tmp_path):
    results = tmp_path / "results"
    results.mkdir()
    (results / "broken.json").write_text("{}")
    page = tmp_path / "performance.md"
    result = run(source_dir, "scripts/performance-page.py", results, page)
    assert result.returncode == 1
    assert "broken.json: not Google Benchmark JSON" in result.stderr
    assert not page.exists()
