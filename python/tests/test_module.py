"""The package itself: it imports, names its version, raises animkit.Error, and its type stubs
cover the whole public API."""
import ast
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
