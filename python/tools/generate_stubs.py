"""Writes the type stubs (animkit/__init__.pyi) of the built animkit module, from the signatures
pybind11 puts at the head of every docstring, so the stubs always match the binary.

    /usr/bin/python3 python/tools/generate_stubs.py BUILD/python

imports animkit from BUILD/python and writes BUILD/python/animkit/__init__.pyi.
"""
import inspect
import pathlib
import re
import sys


def matching_bracket(text, start):
    """Index of the bracket closing the one at text[start]."""
    depth = 0
    for i in range(start, len(text)):
        if text[i] in "[(":
            depth += 1
        elif text[i] in "])":
            depth -= 1
            if depth == 0:
                return i
    return len(text) - 1


def clean_type(text):
    """A pybind11 type name as a stub's annotation."""
    text = text.replace("animkit._animkit.", "").replace("animkit.", "")
    # numpy.ndarray[numpy.float64[m, 3]] and the like: the shape is not a type.
    out, i = "", 0
    while True:
        j = text.find("numpy.ndarray[", i)
        if j < 0:
            break
        out += text[i:j] + "numpy.ndarray"
        i = matching_bracket(text, j + len("numpy.ndarray")) + 1
    out += text[i:]
    return out


def split_top_level(text):
    """Splits a parameter list at the commas outside brackets."""
    parts, depth, current = [], 0, ""
    for ch in text:
        if ch in "[(<{":
            depth += 1
        elif ch in "])>}":
            depth -= 1
        if ch == "," and depth == 0:
            parts.append(current.strip())
            current = ""
        else:
            current += ch
    if current.strip():
        parts.append(current.strip())
    return parts


def clean_parameter(param):
    name, _, rest = param.partition(":")
    annotation, has_default, _ = rest.partition("=")
    stub = name.strip()
    if annotation.strip():
        stub += ": " + clean_type(annotation.strip())
    if has_default:
        stub += " = ..."
    return stub


SIGNATURE = re.compile(r"^(?:\d+\.\s*)?(\w+)\((.*)\)\s*->\s*(.*)$")


def signatures(doc, name):
    """The (parameters, return type) of each overload a pybind11 docstring lists."""
    found = []
    for line in (doc or "").splitlines():
        m = SIGNATURE.match(line.strip())
        if m and m.group(1) == name:
            params = [clean_parameter(p) for p in split_top_level(m.group(2))]
            found.append((params, clean_type(m.group(3).strip())))
    return found


def description(doc, name):
    """The docstring without its signature lines."""
    lines = [line for line in (doc or "").splitlines()
             if not SIGNATURE.match(line.strip()) and line.strip() != "Overloaded function."]
    return "\n".join(lines).strip()


def docstring(text, indent):
    if not text:
        return ""
    text = text.replace('"""', "'''").replace("\\", "\\\\")
    return f'{indent}    """{text}"""\n'


def function_stub(name, obj, indent="", method=False, static=False):
    sigs = signatures(obj.__doc__, name) or [(["*args", "**kwargs"], "typing.Any")]
    out = ""
    for params, returns in sigs:
        if len(sigs) > 1:
            out += f"{indent}@typing.overload\n"
        if static:
            out += f"{indent}@staticmethod\n"
        out += f"{indent}def {name}({', '.join(params)}) -> {returns}:\n"
        out += docstring(description(obj.__doc__, name), indent) or ""
        out += f"{indent}    ...\n"
    return out


def property_stub(name, prop, indent):
    sig = signatures(prop.fget.__doc__, "") if prop.fget else []
    returns = "typing.Any"
    m = re.search(r"\)\s*->\s*(.*)$", (prop.fget.__doc__ or "").splitlines()[0] if prop.fget and prop.fget.__doc__ else "")
    if m:
        returns = clean_type(m.group(1).strip())
    del sig
    out = f"{indent}@property\n{indent}def {name}(self) -> {returns}:\n"
    doc = "\n".join((prop.__doc__ or prop.fget.__doc__ or "").splitlines()[1:]).strip() if prop.fget else ""
    out += docstring(doc, indent) + f"{indent}    ...\n"
    if prop.fset:
        out += f"{indent}@{name}.setter\n{indent}def {name}(self, value: {returns}) -> None: ...\n"
    return out


def class_stub(name, cls):
    bases = [b.__name__ for b in cls.__bases__ if b.__module__.startswith("animkit")]
    if issubclass(cls, Exception):
        bases = ["ValueError"]
    out = f"class {name}({', '.join(bases)}):\n" if bases else f"class {name}:\n"
    out += docstring(inspect.cleandoc(cls.__doc__ or ""), "")
    if issubclass(cls, Exception):
        return out + "    ...\n"
    members = getattr(cls, "__members__", None)
    if members:  # a pybind11 enum
        for member in members:
            out += f"    {member}: typing.ClassVar[{name}]\n"
    for attr, value in cls.__dict__.items():
        if attr.startswith("__") and attr not in ("__init__", "__repr__", "__eq__", "__len__",
                                                   "__getitem__", "__iter__", "__enter__",
                                                   "__exit__"):
            continue
        if attr.startswith("_") and not attr.startswith("__"):
            continue
        if members and attr in members:
            continue
        if isinstance(value, property):
            out += property_stub(attr, value, "    ")
        elif isinstance(value, staticmethod):
            out += function_stub(attr, value.__func__, "    ", static=True)
        elif callable(value):
            out += function_stub(attr, value, "    ", method=True)
    return out


def main():
    build = pathlib.Path(sys.argv[1])
    sys.path.insert(0, str(build))
    import animkit
    from animkit import _animkit

    out = '"""Type stubs of animkit, generated from the built module by tools/generate_stubs.py."""\n'
    # The names pybind11's signatures use (typing's generics, os.PathLike for paths).
    out += "import os\nimport typing\nfrom typing import (Any, Callable, Dict, Iterable, Iterator, List,\n"
    out += "                    Optional, Sequence, Set, Tuple, Union)\n\nimport numpy\n\n"
    out += "__version__: str\n\n"
    for name in sorted(animkit.__all__):
        value = getattr(_animkit, name)
        if inspect.isclass(value):
            out += class_stub(name, value) + "\n"
        elif callable(value):
            out += function_stub(name, value) + "\n"
        else:
            out += f"{name}: {type(value).__name__}\n"
    (build / "animkit" / "__init__.pyi").write_text(out)


if __name__ == "__main__":
    main()
