"""The type stubs installed beside the module say what the module's own signatures say."""
import pathlib

import contactbench as cb


def test_installed_stubs_match_the_module(make_stubs):
    # The stubs are written from the module's pybind11 signatures; the installed ones (beside __init__.py, in
    # the build tree or a wheel's site-packages) must be exactly what the module generates now.
    package = pathlib.Path(cb.__file__).parent
    assert (package / "py.typed").is_file()  # PEP 561: type checkers read the stubs of an installed package
    for name, text in make_stubs.stubs().items():
        assert (package / name).read_text(encoding="utf-8") == text, (
            f"{name} differs from the module's signatures: rerun python/make_stubs.py"
        )


def test_stubs_declare_every_public_name(make_stubs):
    stubs = make_stubs.stubs()["__init__.pyi"]
    public = [name for name in dir(cb) if not name.startswith("_") and name != "paper"]
    missing = [name for name in public if f"class {name}" not in stubs and f"def {name}(" not in stubs]
    assert not missing


def test_stubs_are_valid_python_with_the_documented_keywords(make_stubs):
    import ast

    tree = ast.parse(make_stubs.stubs()["__init__.pyi"])
    solver = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "BemSolver")
    init = next(n for n in solver.body if isinstance(n, ast.FunctionDef) and n.name == "__init__")
    keywords = [a.arg for a in init.args.kwonlyargs]
    # The scene keys of a BEM method that a solver object takes (app/methods/bem_settings.cpp), typed.
    assert keywords == ["hardness", "adhesion", "threads", "tolerance", "max_iterations", "periodic", "precision",
                        "connectivity", "solver", "adhesive_solver"]
