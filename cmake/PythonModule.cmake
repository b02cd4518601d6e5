# The Python module (python/, issue 16) is built for Debian's interpreter, /usr/bin/python3, with Debian's
# pybind11-dev and python3-numpy: not for the first `python3` on PATH, which may be another installation
# (pyenv, conda) without numpy or pybind11. CB_PYTHON_EXECUTABLE chooses another interpreter on purpose.
# CB_BUILD_PYTHON defaults to ON exactly when that interpreter, its headers, numpy and pybind11 are found.
set(CB_PYTHON_EXECUTABLE "/usr/bin/python3" CACHE FILEPATH
    "Python interpreter the contactbench module is built for and tested with (default: Debian's)")

set(Python3_EXECUTABLE "${CB_PYTHON_EXECUTABLE}")
find_package(Python3 QUIET COMPONENTS Interpreter Development.Module NumPy)
# Only with that interpreter found: pybind11's config would otherwise search PATH for its own python (and fail
# hard on a pyenv shim).
if(Python3_FOUND AND Python3_NumPy_FOUND)
  find_package(pybind11 2.6 QUIET CONFIG)
endif()
set(_cb_python_default OFF)
if(Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND)
  set(_cb_python_default ON)
endif()
option(CB_BUILD_PYTHON "Build the Python module contactbench (pybind11, for CB_PYTHON_EXECUTABLE)"
       ${_cb_python_default})

if(CB_BUILD_PYTHON)
  if(NOT (Python3_FOUND AND Python3_NumPy_FOUND AND pybind11_FOUND))
    message(FATAL_ERROR "CB_BUILD_PYTHON: needs ${CB_PYTHON_EXECUTABLE} with its headers and numpy, and "
                        "pybind11 (Debian: apt-get install python3-dev python3-numpy pybind11-dev)")
  endif()
  # The static libraries end up inside a shared module.
  set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  # Where `cmake --install` puts the module, relative to the prefix: Debian's python3 searches
  # <prefix>/lib/python3.X/dist-packages for the prefixes /usr and /usr/local; for any other prefix, add that
  # folder to PYTHONPATH.
  set(CB_PYTHON_INSTALL_DIR "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages"
      CACHE STRING "Install folder of the Python module, relative to CMAKE_INSTALL_PREFIX")
  message(STATUS "contactbench: Python module for ${Python3_EXECUTABLE} (Python ${Python3_VERSION}, numpy "
                 "${Python3_NumPy_VERSION}), installed to <prefix>/${CB_PYTHON_INSTALL_DIR}")
else()
  message(STATUS "contactbench: no Python module (CB_BUILD_PYTHON is OFF)")
endif()
