// The Python module's shared pieces: one registration function per area (each in its own file, so that a
// change of one library's API is a local edit) and the conversions between numpy arrays and the C++ arrays.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench::python {

namespace py = pybind11;

void register_errors(py::module_& m);
void register_surface(py::module_& m);
void register_sweep(py::module_& m);
void register_theories(py::module_& m);
void register_bem(py::module_& m);
void register_scene(py::module_& m);

// Heights [m] from a numpy array: exactly a 2-D, C-contiguous float64 array (rows = y) of at least one point,
// copied once into the C++ surface's own storage. Anything else (another dtype, other dimensions, a strided
// view) throws Error naming `argument`, what it expected and what it got: nothing is converted silently.
HeightMap height_map_from_array(const py::handle& array, const std::string& argument);

// A read-only numpy view of `map` (float64, C order, rows = y), no copy: `owner` (the Python object that
// holds the map) is kept alive by the view.
py::array view_of(const HeightMap& map, const py::handle& owner);

// A read-only 1-D numpy view of `values` (float64 or int64), no copy, keeping `owner` alive.
py::array view_of(const std::vector<Real>& values, const py::handle& owner);
py::array view_of(const std::vector<Index>& values, const py::handle& owner);

// `threads` as the CLI accepts it (--threads): 1 to 1024, else Error naming the argument.
int checked_threads(int threads);

// Releases the GIL while `work` runs; afterwards raises KeyboardInterrupt (or whatever a signal handler
// raised) if Ctrl-C was pressed meanwhile.
void check_signals();

}  // namespace contactbench::python
