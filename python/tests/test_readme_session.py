"""The README's Python session ("From Python") runs as written and prints what it shows."""
import doctest
import os
import re

import pytest


def readme_session(source_dir):
    text = (source_dir / "README.md").read_text()
    start = text.index("The CLI examples above, from Python")
    block = re.search(r"```python\n(.*?)```", text[start:], re.S)
    assert block, "no python block after the session's introduction"
    # Comments after a statement are the README's notes, not part of the expected output.
    return block.group(1)


def test_readme_python_session_runs_as_shown(source_dir, tmp_path, monkeypatch):
    session = readme_session(source_dir)
    (tmp_path / "data").symlink_to(source_dir / "data")
    monkeypatch.chdir(tmp_path)
    parser = doctest.DocTestParser()
    test = parser.get_doctest(session, {}, "README.md", "README.md", 0)
    assert len(test.examples) >= 15
    runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    runner.run(test)
    result = runner.summarize(verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} README lines differ"
    for picture in ("star.png", "drape.png"):
        assert (tmp_path / picture).stat().st_size > 1000
    assert (tmp_path / "walk-locked.bvh").read_text().startswith("HIERARCHY")


if __name__ == "__main__":
    pytest.main([__file__])
