"""The Python sessions of the README and of the documentation's Python page run as written and
print what they show; the README's C++ example is the file CMake builds and a test runs."""
import doctest
import re

import pytest


def python_block(text, after):
    start = text.index(after)
    block = re.search(r"```python\n(.*?)```", text[start:], re.S)
    assert block, f"no python block after {after!r}"
    # Comments after a statement are the notes, not part of the expected output.
    return block.group(1)


def run_session(session, name, source_dir, tmp_path, monkeypatch):
    (tmp_path / "data").symlink_to(source_dir / "data")
    monkeypatch.chdir(tmp_path)
    test = doctest.DocTestParser().get_doctest(session, {}, name, name, 0)
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} lines of {name} differ"
    return len(test.examples)


def test_readme_python_example_runs_as_shown(source_dir, tmp_path, monkeypatch):
    text = (source_dir / "README.md").read_text()
    examples = run_session(python_block(text, "## From Python"), "README.md", source_dir,
                           tmp_path, monkeypatch)
    assert examples >= 8
    assert (tmp_path / "walk.glb").read_bytes()[:4] == b"glTF"
    assert (tmp_path / "drape.glb").read_bytes()[:4] == b"glTF"


def test_python_page_session_runs_as_shown(source_dir, tmp_path, monkeypatch):
    text = (source_dir / "docs" / "python.md").read_text()
    session = python_block(text, "The CLI examples above, from Python")
    assert run_session(session, "docs/python.md", source_dir, tmp_path, monkeypatch) >= 15
    for picture in ("star.png", "drape.png"):
        assert (tmp_path / picture).stat().st_size > 1000
    assert (tmp_path / "walk-locked.bvh").read_text().startswith("HIERARCHY")


def test_readme_cpp_example_is_the_built_file(source_dir):
    text = (source_dir / "README.md").read_text()
    block = re.search(r"```cpp\n(.*?)```", text, re.S).group(1)
    source = (source_dir / "examples" / "cpp" / "drape_to_gltf.cpp").read_text()
    # The file is the README's block after its two comment lines.
    assert source.split("\n", 2)[2] == block


if __name__ == "__main__":
    pytest.main([__file__])
