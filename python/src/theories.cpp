// The multi-plateaus model and the analytic theories, each as a load-area curve (theories/, docs/theory.md
// sections 4, 5 and 8). Loads are P/(E* A0), finite, > 0 and ascending.
#include <pybind11/stl.h>

#include <optional>
#include <vector>

#include "bindings.hpp"
#include "contactbench/theories/bgt_linear.hpp"
#include "contactbench/theories/bush_gibson_thomas.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/persson.hpp"
#include "contactbench/theories/plateau_hertz.hpp"
#include "contactbench/theories/plateau_model.hpp"

namespace contactbench::python {

void register_theories(py::module_& m) {
  m.def("plateau_model", &plateau_model, py::arg("sweep"),
        "The multi-plateaus model of Wang, Liang and Yan (docs/theory.md section 4, eq. 3) at every level of "
        "the sweep: P(z)/(E* A0) and A_c(z)/A0.");
  m.def(
      "plateau_curve_at_loads",
      [](const SweepCurve& sweep, const LoadAreaCurve& model, const std::vector<Real>& loads) {
        return plateau_curve_at_loads(sweep, model, loads);
      },
      py::arg("sweep"), py::arg("model"), py::arg("loads"),
      "The plateau model (model = plateau_model(sweep)) at the requested loads P/(E* A0), exactly (no "
      "interpolation error).");
  m.def("plateau_hertz", &plateau_hertz, py::arg("paper_model"),
        "The Hertz-consistent plateau variant (the project's, not the paper's; docs/theory.md section 8) at "
        "every level: P/sqrt(2), A_c/2 of paper_model = plateau_model(sweep).");
  m.def(
      "plateau_hertz_curve_at_loads",
      [](const SweepCurve& sweep, const LoadAreaCurve& model, const std::vector<Real>& loads) {
        return plateau_hertz_curve_at_loads(sweep, model, loads);
      },
      py::arg("sweep"), py::arg("paper_model"), py::arg("loads"),
      "The Hertz-consistent plateau variant at the requested loads P/(E* A0) (NaN where the paper's model "
      "reaches full contact).");
  m.def(
      "gw_mccool_curve",
      [](const SpectralMoments& moments, const std::vector<Real>& loads, std::optional<Real> nominal_area) {
        return gw_mccool_curve(moments, loads, nominal_area);
      },
      py::arg("moments"), py::arg("loads"), py::kw_only(), py::arg("nominal_area") = py::none(),
      "Greenwood-Williamson with McCool's parameters from the profile moments (docs/theory.md section 5). "
      "nominal_area A0 [m^2] turns the spot density into spot counts. Refuses anisotropy above 5 %.");
  m.def(
      "bgt_curve",
      [](const SpectralMoments& moments, const std::vector<Real>& loads, std::optional<Real> nominal_area) {
        py::gil_scoped_release unlocked;
        return bgt_curve(moments, loads, nominal_area);
      },
      py::arg("moments"), py::arg("loads"), py::kw_only(), py::arg("nominal_area") = py::none(),
      "Bush-Gibson-Thomas (elliptic summits, docs/theory.md section 5); nominal_area A0 [m^2] for spot "
      "counts.");
  m.def(
      "bgt_linear_curve",
      [](const SpectralMoments& moments, const std::vector<Real>& loads) {
        return bgt_linear_curve(moments, loads);
      },
      py::arg("moments"), py::arg("loads"),
      "The BGT linear law, BGT's small-load limit (docs/theory.md section 5).");
  m.def(
      "persson_curve",
      [](const SpectralMoments& moments, const std::vector<Real>& loads) {
        return persson_curve(moments, loads);
      },
      py::arg("moments"), py::arg("loads"),
      "Persson's theory at full magnification, A/A0 = erf(load/sqrt(m2)) (docs/theory.md section 5).");
}

}  // namespace contactbench::python
