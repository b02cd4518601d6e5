"""Builds the Python package contactbench with the project's CMake (scikit-build; see pyproject.toml).

Only the libraries and the package are built (no tests, benchmarks or program), for the interpreter that runs
the build, and only CMake's `python` install component goes into the wheel."""
import pathlib
import re
import sys

from skbuild import setup

SOURCE = pathlib.Path(__file__).resolve().parent


def project_version():
    """The version of CMakeLists.txt's project() call: one place for the program, the library and the wheel."""
    text = (SOURCE / "CMakeLists.txt").read_text(encoding="utf-8")
    found = re.search(r"project\(\s*contactbench\s+VERSION\s+([0-9][0-9.]*)", text)
    if not found:
        sys.exit("setup.py: no `project(contactbench VERSION x.y.z` in CMakeLists.txt")
    return found.group(1)


def pybind11_cmake_args():
    """pybind11 from PyPI (an isolated build) is found through its own CMake folder; Debian's pybind11-dev is
    found by CMake without help."""
    try:
        import pybind11
    except ImportError:
        return []
    return ["-Dpybind11_DIR=" + pybind11.get_cmake_dir()]


setup(
    version=project_version(),
    packages=["contactbench"],
    package_dir={"contactbench": "python/contactbench"},
    package_data={"contactbench": ["__init__.pyi", "paper.pyi", "py.typed"]},
    cmake_install_dir=".",
    cmake_install_target="install-python-package",
    cmake_args=[
        "-DCMAKE_BUILD_TYPE=Release",
        "-DCB_PYTHON_EXECUTABLE=" + sys.executable,
        "-DCB_BUILD_PYTHON=ON",
        "-DCB_BUILD_TESTS=OFF",
        "-DCB_BUILD_BENCHMARKS=OFF",
        "-DCB_WITH_MPI=OFF",
        # scikit-build takes the package's files from the install folder's copy of package_dir, python/contactbench
        # (into site-packages/contactbench/); anything installed elsewhere would land in the wheel's data.
        "-DCB_PYTHON_INSTALL_DIR=python",
    ]
    + pybind11_cmake_args(),
)
