"""The package itself: it imports, names its version, raises animkit.Error, and its type stubs
cover the whole public API; the threads tests' GIL probe works."""
import ast
import builtins
import pathlib
import time

import animkit


def test_version_is_the_projects():
    assert animkit.__version__.count(".") == 2


def test_error_is_a_value_error_named_in_animkit():
    assert issubclass(animkit.Error, ValueError)
    assert animkit.Error.__module__ == "animkit"


def test_stubs_parse_and_name_every_public_symbol():
    stub = pathlib.Path(animkit.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text())
    defined = {node.name for node in tree.body if isinstance(node, (ast.ClassDef, ast.FunctionDef))}
    defined |= {t.id for node in tree.body if isinstance(node, ast.AnnAssign)
                for t in [node.target] if isinstance(t, ast.Name)}
    missing = [name for name in animkit.__all__ if name not in defined]
    assert not missing, f"names without a stub: {missing}"


def test_stub_annotations_name_only_defined_things():
    stub = pathlib.Path(animkit.__file__).with_name("__init__.pyi")
    tree = ast.parse(stub.read_text())
    known = set(dir(builtins)) | {"os", "typing", "numpy"}
    for node in tree.body:
        if isinstance(node, (ast.ClassDef, ast.FunctionDef)):
            known.add(node.name)
        elif isinstance(node, ast.ImportFrom):
            known |= {alias.asname or alias.name for alias in node.names}
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            known.add(node.target.id)
    unknown = set()
    for node in ast.walk(tree):
        annotations = []
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            annotations = [a.annotation for a in node.args.args + node.args.kwonlyargs]
            annotations += [node.returns]
        for annotation in annotations:
            for name in ast.walk(annotation) if annotation is not None else []:
                if isinstance(name, ast.Name) and name.id not in known:
                    unknown.add(name.id)
    assert not unknown, f"stubs use undefined names: {sorted(unknown)}"


def test_run_watched_tells_a_held_gil_from_a_released_one(run_watched):
    # The threads tests' probe (conftest.py) on known cases: Python code holds the GIL from
    # start to end, so this thread gets no turn while it runs; time.sleep lets go of it.
    def busy():
        return sum(i * i for i in range(300_000))

    turns, total, _ = run_watched(busy)
    assert turns == 0 and total > 0
    turns, _, _ = run_watched(lambda: [time.sleep(0.005) for _ in range(10)])
    assert turns > 0
