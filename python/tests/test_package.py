"""The package as Python users see it: its version is the project's, its types are named after it, and its
submodule imports like a package's."""
import re

import contactbench as cb


def test_version_is_the_projects(source_dir):
    text = (source_dir / "CMakeLists.txt").read_text(encoding="utf-8")
    assert cb.__version__ == re.search(r"project\(contactbench VERSION ([0-9.]+)", text).group(1)


def test_public_types_are_named_after_the_package():
    for name in ["Surface", "BemSolver", "BemResult", "LoadAreaCurve", "MethodCurve", "Error", "InputError"]:
        assert getattr(cb, name).__module__ == "contactbench", name
    assert repr(cb.Grid) == "<class 'contactbench.Grid'>"


def test_paper_imports_as_a_submodule():
    import contactbench.paper
    from contactbench.paper import grid

    assert contactbench.paper is cb.paper and grid().nx == 256
