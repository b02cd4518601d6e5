// The compiled part `_contactbench` of the Python package `contactbench` (issue 16): the C++ libraries as
// they are, no second implementation. python/contactbench/__init__.py imports it and re-exports its names.
#include "bindings.hpp"

PYBIND11_MODULE(_contactbench, m) {
  m.doc() =
      "contactbench: rough-surface contact, cheap models against a boundary-element ground truth.\n\n"
      "SI units everywhere: lengths [m], pressures and moduli [Pa], wavevectors [1/m]. Every load argument "
      "(named load(s) or passed by position) is dimensionless, P/(E* A0); a mean pressure P/A0 [Pa] is taken "
      "only by the keyword mean_pressure=. Arrays are numpy float64 in C order "
      "with rows along y: heights[iy, ix] is the height at (x, y) = (ix dx, iy dy) (docs/theory.md section "
      "0). Arrays that the module returns are read-only views of its own results (no copy); heights passed "
      "in "
      "are copied once into the surface. Bad arguments raise contactbench.Error (a ValueError) with the "
      "message the command line prints; bad files raise contactbench.InputError naming the file and line.\n"
      "See docs/python.md.";
  m.attr("__version__") = CB_VERSION;
  using namespace contactbench::python;
  register_errors(m);
  register_surface(m);
  register_sweep(m);
  register_theories(m);
  register_bem(m);
  register_scene(m);
}
