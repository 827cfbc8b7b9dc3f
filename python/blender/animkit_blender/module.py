"""Finding the animkit Python module from inside Blender.

The add-on is pure Python; the simulation and the foot locking run in the compiled module
`animkit`, which `cmake --install build/release` puts in /usr/local/lib/python3.11/dist-packages
(a folder on Debian Blender's Python path). Operators call `load_animkit()` when they run, not
when the add-on registers, so the add-on can be enabled before the module is installed and
says how to install it instead of failing to load.
"""
import importlib

INSTALL_HINT = (
    "the Python module 'animkit' is not installed: build animkit and run "
    "'cmake --install build/release' (it installs into Python's dist-packages, which Blender "
    "reads), or add the build's python folder to sys.path")


class AnimkitMissing(RuntimeError):
    """The module `animkit` cannot be imported; the message says how to install it."""


def load_animkit():
    """Returns the imported `animkit` module; raises AnimkitMissing with install hints."""
    try:
        return importlib.import_module("animkit")
    except ImportError as error:
        raise AnimkitMissing(f"{INSTALL_HINT} ({error})") from error


def animkit_error_types():
    """The exception types an animkit call raises for bad input (animkit.Error is a
    ValueError), for `except` clauses that turn them into operator reports."""
    try:
        return (importlib.import_module("animkit").Error,)
    except (ImportError, AttributeError):
        return (ValueError,)
