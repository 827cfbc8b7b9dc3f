"""animkit: inverse kinematics and mass-spring cloth, from Python.

The classes and functions are the C++ library's (bound with pybind11): the same solvers, the same
defaults and the same error messages as the `animkit` command-line tool. Bad input raises
animkit.Error (a ValueError) naming the problem. Arrays come and go as numpy float64 arrays;
quaternions are (w, x, y, z). See help(animkit.<name>) and docs/python.md.
"""
from . import _animkit
from ._animkit import *  # noqa: F401,F403 (the module's whole public API)
from ._animkit import __version__  # noqa: F401

# Classes and functions say they live in `animkit`, where users import them from (help(),
# repr() of types and the generated stubs use it).
for _name in dir(_animkit):
    _value = getattr(_animkit, _name)
    if not _name.startswith("_") and getattr(_value, "__module__", None) == "animkit._animkit":
        try:
            _value.__module__ = "animkit"
        except (AttributeError, TypeError):  # built-in functions keep theirs
            pass
del _name, _value

__all__ = [name for name in dir(_animkit) if not name.startswith("_")]
