// numpy <-> C++ arrays (bindings.hpp): heights in (one copy, strictly checked), fields and curves out
// (views).
#include <algorithm>
#include <cstdint>

#include "bindings.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench::python {

namespace {

std::string describe_array(const py::array& a) {
  std::string shape = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d)
    shape += (d ? ", " : "") + std::to_string(a.shape(d));
  if (a.ndim() == 1) shape += ",";
  shape += ")";
  return std::string(py::str(a.dtype())) + " array of shape " + shape;
}

py::array read_only(py::array a) {
  a.attr("setflags")(py::arg("write") = false);
  return a;
}

template <class T>
py::array vector_view(const std::vector<T>& values, const py::handle& owner) {
  const py::ssize_t n = static_cast<py::ssize_t>(values.size());
  return read_only(py::array_t<T>({n}, {static_cast<py::ssize_t>(sizeof(T))}, values.data(), owner));
}

}  // namespace

HeightMap height_map_from_array(const py::handle& object, const std::string& argument) {
  const std::string expected = argument + ": expected a 2-D, C-contiguous numpy array of float64 (rows = y) ";
  if (!py::isinstance<py::array>(object))
    throw Error(expected + "[m], got a " +
                std::string(py::str(py::type::handle_of(object).attr("__name__"))));
  const auto array = py::reinterpret_borrow<py::array>(object);
  if (!array.dtype().is(py::dtype::of<double>()))
    throw Error(expected + "[m], got a " + describe_array(array) + " (convert with numpy.asarray(a, float))");
  if (array.ndim() != 2) throw Error(expected + "[m], got a " + describe_array(array));
  if (!(array.flags() & py::array::c_style))
    throw Error(expected + "[m], got a strided view (non-contiguous); pass numpy.ascontiguousarray(a)");
  const py::ssize_t ny = array.shape(0), nx = array.shape(1);
  if (nx < 1 || ny < 1) throw Error(expected + "[m] with at least one point, got a " + describe_array(array));
  HeightMap heights(ny, nx);
  const auto* data = static_cast<const double*>(array.data());
  std::copy(data, data + nx * ny, heights.data());
  return heights;
}

py::array view_of(const HeightMap& map, const py::handle& owner) {
  const auto row = static_cast<py::ssize_t>(map.cols() * sizeof(double));
  return read_only(
      py::array_t<double>({static_cast<py::ssize_t>(map.rows()), static_cast<py::ssize_t>(map.cols())},
                          {row, static_cast<py::ssize_t>(sizeof(double))}, map.data(), owner));
}

py::array view_of(const std::vector<Real>& values, const py::handle& owner) {
  return vector_view(values, owner);
}

py::array view_of(const std::vector<Index>& values, const py::handle& owner) {
  static_assert(sizeof(Index) == sizeof(std::int64_t));
  return vector_view(values, owner);
}

int checked_threads(int threads) {
  if (threads < 1 || threads > 1024)
    throw Error("threads: accepted values are whole numbers from 1 to 1024, got " + std::to_string(threads));
  return threads;
}

void check_signals() {
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

}  // namespace contactbench::python
