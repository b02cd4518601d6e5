"""contactbench: rough-surface contact, cheap models against a boundary-element ground truth.

SI units everywhere: lengths [m], pressures and moduli [Pa], wavevectors [1/m]. Loads are dimensionless,
P/(E* A0), wherever an argument is called `load(s)` or passed by position; a mean pressure P/A0 [Pa] is taken
only by the keyword `mean_pressure=`. Arrays are numpy float64 in C order with rows along y: heights[iy, ix] is
the height at (x, y) = (ix dx, iy dy). Arrays the module returns are read-only views of its own results (no
copy). Bad arguments raise contactbench.Error (a ValueError) with the command line's message; bad files raise
contactbench.InputError naming the file and line. See docs/python.md.
"""
# The compiled part (_contactbench) hands numpy arrays out and takes them in; without numpy it would import and
# then fail at the first array with a bare "No module named numpy". Say so here, at import, with the remedy.
try:
    import numpy as _numpy  # noqa: F401
except ImportError as _missing:
    import sys as _sys

    raise ImportError(
        "contactbench needs numpy, which this interpreter (" + _sys.executable + ") does not have: "
        "install it (pip install numpy; on Debian apt-get install python3-numpy and use /usr/bin/python3, "
        "or a venv made with --system-site-packages)"
    ) from _missing

from . import _contactbench
from ._contactbench import *  # noqa: F401,F403
from ._contactbench import __version__, paper  # noqa: F401

# `import contactbench.paper` and `from contactbench.paper import grid` work like a package's submodule.
_sys_modules = __import__("sys").modules
_sys_modules[__name__ + ".paper"] = paper
del _sys_modules

# Public names report the package they are used from (contactbench.Surface, not contactbench._contactbench):
# reprs, help() and the type stubs then all say the same.
for _name in dir(_contactbench):
    _value = getattr(_contactbench, _name)
    if isinstance(_value, type) and getattr(_value, "__module__", "") == _contactbench.__name__:
        _value.__module__ = __name__
del _name, _value
