"""The package itself: it imports, names its version, raises animkit.Error, and its type stubs
cover the whole public API."""
import ast
import builtins
import pathlib

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
