#!/usr/bin/python3
"""Writes the type stubs of the package contactbench (python/contactbench/__init__.pyi and paper.pyi) from the
signatures pybind11 puts at the head of every docstring of the built module, so that editors and type checkers
see the same signatures as help() does. No stub generator is a Debian package, hence this small one.

  PYTHONPATH=build/release/python /usr/bin/python3 python/make_stubs.py          # rewrite the stubs
  PYTHONPATH=build/release/python /usr/bin/python3 python/make_stubs.py --check  # exit 1 if they differ

python/tests/test_stubs.py runs the same comparison against the stubs installed beside the module."""
import argparse
import pathlib
import re
import sys

HEADER = '''"""Type stubs of contactbench, written by python/make_stubs.py from the module's own signatures."""
# Generated: edit the bindings (python/src/) and rerun python/make_stubs.py, never this file.
import os
from typing import Any, Dict, List, Optional, Tuple, Union

import numpy
'''
# Defaults kept as written when they are plain literals; anything else (an object's repr) becomes "...".
LITERAL = re.compile(r"^(None|True|False|-?[0-9.e+-]+|'[^']*'|\"[^\"]*\")$")


def clean_type(text):
    """pybind11's type names as the stubs spell them: the package's own types by their bare names."""
    text = re.sub(r"\bcontactbench\._contactbench\.paper\.", "paper.", text)
    text = re.sub(r"\bcontactbench\._contactbench\.", "", text)
    text = re.sub(r"\bcontactbench\.", "", text)
    # Heights are taken as any object and checked by the module itself (contactbench.Error, not a TypeError,
    # for a list); what it accepts is a numpy array.
    return re.sub(r"^handle$", "numpy.ndarray", text)


def split_top_level(text):
    """Splits a parameter list at the commas outside brackets and quotes."""
    parts, depth, quote, start = [], 0, None, 0
    for i, c in enumerate(text):
        if quote:
            quote = None if c == quote else quote
        elif c in "'\"":
            quote = c
        elif c in "[(":
            depth += 1
        elif c in "])":
            depth -= 1
        elif c == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def parameter(text, first_of_method):
    """One parameter of a pybind11 signature as a stub writes it."""
    if text in ("*", "/") or text.startswith("*"):
        return clean_type(text)
    name, _, rest = text.partition(":")
    annotation, _, default = rest.partition("=")
    if first_of_method and name.strip() == "self":
        return "self"
    written = name.strip() + ": " + clean_type(annotation.strip())
    if default:
        value = default.strip()
        written += " = " + (value if LITERAL.match(value) else "...")
    return written


def signatures(name, doc):
    """Every "name(params) -> result" line pybind11 wrote at the head of doc (several when overloaded)."""
    pattern = re.compile(r"^(?:\d+\. )?" + re.escape(name) + r"\((.*)\) -> (.+)$")
    found = [pattern.match(line) for line in (doc or "").splitlines()]
    return [(m.group(1), m.group(2)) for m in found if m]


def function_stub(name, doc, indent="", method=False):
    lines = []
    found = signatures(name, doc)
    if not found:
        raise SystemExit(f"make_stubs: no signature in the docstring of {name}")
    for params, result in found:
        written = [parameter(p, method and k == 0) for k, p in enumerate(split_top_level(params))]
        if len(found) > 1:
            lines.append(indent + "@overload")
        lines.append(f"{indent}def {name}({', '.join(written)}) -> {clean_type(result)}: ...")
    return lines


def keyword_signature(cls):
    """A class whose __init__ takes **kwargs declares its keywords on a typed line of its own docstring
    ("Name(params)"), built from the declaration the keywords are checked against (BemSolver)."""
    for line in (cls.__doc__ or "").splitlines():
        if line.startswith(cls.__name__ + "("):
            return line[len(cls.__name__) + 1 : line.rindex(")")]
    return None


def property_stub(name, prop, indent):
    doc = (prop.fget.__doc__ or "").splitlines()
    match = re.match(r"^\((?:self|arg0): [^)]*\) -> (.+)$", doc[0]) if doc else None
    if not match:
        raise SystemExit(f"make_stubs: no type for the property {name}")
    kind = clean_type(match.group(1))
    if prop.fset is not None:
        return [f"{indent}{name}: {kind}"]
    return [f"{indent}@property", f"{indent}def {name}(self) -> {kind}: ..."]


def class_stub(cls):
    bases = [b.__name__ for b in cls.__bases__ if b.__name__ not in ("pybind11_object", "object")]
    lines = [f"class {cls.__name__}{'(' + ', '.join(bases) + ')' if bases else ''}:"]
    body = []
    for name, member in sorted(vars(cls).items()):
        if name.startswith("_") and name not in ("__init__", "__len__", "__repr__"):
            continue
        if isinstance(member, property):
            body += property_stub(name, member, "    ")
        elif callable(member) or type(member).__name__ == "instancemethod":
            doc = getattr(member, "__doc__", None)
            if name == "__init__" and not signatures(name, doc):
                continue  # made by the module only (a report, a curve): no constructor to declare
            if name == "__init__" and "**kwargs" in (doc or ""):
                params = keyword_signature(cls)
                written = ["self"] + [parameter(p, False) for p in split_top_level(params)]
                body.append(f"    def __init__({', '.join(written)}) -> None: ...")
            else:
                body += function_stub(name, doc, "    ", method=True)
    if issubclass(cls, BaseException):
        body += [f"    {name}: {kind}" for name, kind in exception_attributes(cls)]
    return lines + (body or ["    ..."])


def exception_attributes(cls):
    """The attributes the error translator (python/src/errors.cpp) sets on each exception."""
    return {"InputError": [("path", "str"), ("line", "int")], "SceneError": [("problems", "List[str]")]}.get(
        cls.__name__, []
    )


def module_stub(module, header):
    lines = header.splitlines()
    names = [n for n in sorted(vars(module)) if not n.startswith("_")]
    for name in names:
        value = getattr(module, name)
        if isinstance(value, type):
            lines += ["", ""] + class_stub(value)
    lines.append("")
    for name in names:
        value = getattr(module, name)
        if callable(value) and not isinstance(value, type):
            lines += function_stub(name, value.__doc__)
    return "\n".join(lines) + "\n"


def stubs():
    """{file name: text} of the package's stubs, from the module that is imported (the built one: this file's
    own folder holds the package's sources without the compiled part, so it is taken off the path)."""
    here = str(pathlib.Path(__file__).resolve().parent)
    sys.path[:] = [p for p in sys.path if str(pathlib.Path(p or ".").resolve()) != here]
    import contactbench
    from contactbench import _contactbench

    header = HEADER + "\nfrom . import paper as paper\n\n__version__: str\n"
    paper_header = HEADER.replace("Type stubs of contactbench", "Type stubs of contactbench.paper") + (
        "\nfrom . import Grid, SelfAffinePsd\n"
    )
    assert contactbench.paper is _contactbench.paper
    return {
        "__init__.pyi": module_stub(_contactbench, header),
        "paper.pyi": module_stub(_contactbench.paper, paper_header),
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare with the stubs in the tree; exit 1 if not equal")
    folder = pathlib.Path(__file__).resolve().parent / "contactbench"
    arguments = parser.parse_args()
    stale = []
    for name, text in stubs().items():
        path = folder / name
        if arguments.check:
            if not path.exists() or path.read_text(encoding="utf-8") != text:
                stale.append(name)
        else:
            path.write_text(text, encoding="utf-8")
    if stale:
        sys.exit(f"make_stubs: {', '.join(stale)} differ from the module's signatures; rerun python/make_stubs.py")


if __name__ == "__main__":
    main()
