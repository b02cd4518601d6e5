#include "contactbench/theories/plateau_hertz.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/plateau_model.hpp"
#include "contactbench/theories/requested_loads.hpp"

namespace contactbench {

namespace {

constexpr const char* kName = "plateau_hertz";
// Contact radius over bearing radius of an elastic paraboloid, sqrt(R delta) / sqrt(2 R delta)
// (docs/theory.md section 8.1): the load scales with it, the area with its square.
const Real kRadiusRatio = 1 / std::numbers::sqrt2;

std::string variant_parameters(const std::string& paper_parameters) {
  return paper_parameters +
         ", Hertz-consistent contact radius a = r_b/sqrt(2) (the project's variant, not the "
         "paper's model)";
}

}  // namespace

LoadAreaCurve plateau_hertz(const LoadAreaCurve& paper_model) {
  LoadAreaCurve curve = paper_model;
  curve.method = kName;
  curve.parameters = variant_parameters(paper_model.parameters);
  for (Real& load : curve.load)
    load *= kRadiusRatio;
  for (Real& area : curve.area_fraction)
    area *= kRadiusRatio * kRadiusRatio;
  return curve;
}

LoadAreaCurve plateau_hertz_curve_at_loads(const SweepCurve& sweep, const LoadAreaCurve& paper_model,
                                           std::span<const Real> loads) {
  validate_loads(loads, kName);
  // P_H(z) = P(z)/sqrt(2): the variant carries `load` where the paper's model carries sqrt(2) x load.
  std::vector<Real> paper_loads(loads.begin(), loads.end());
  for (Real& load : paper_loads)
    load /= kRadiusRatio;
  const LoadAreaCurve paper = plateau_curve_at_loads(sweep, paper_model, paper_loads);

  LoadAreaCurve curve;
  curve.method = kName;
  curve.parameters = variant_parameters(paper_model.parameters);
  curve.seconds = paper_model.seconds;
  const Real highest = paper_model.load.empty() ? 0 : paper_model.load.back();
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  bool beyond = false;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    curve.load.push_back(loads[k]);
    if (paper_loads[k] > highest) {  // full contact or past the paper's last level: no answer
      beyond = true;
      curve.area_fraction.push_back(nan);
      curve.separation.push_back(nan);
      curve.spots.push_back(nan);
      continue;
    }
    curve.area_fraction.push_back(paper.area_fraction[k] * kRadiusRatio * kRadiusRatio);
    curve.separation.push_back(paper.separation[k]);
    curve.spots.push_back(paper.spots[k]);
  }
  if (beyond)
    curve.parameters += "; no answer (NaN) for loads above " + format_number(highest * kRadiusRatio) +
                        ", where the cut reaches the lowest level swept";
  return curve;
}

Real plateau_hertz_stiffness(Real area_fraction, Real spots, Real nominal_area) {
  return 2 * std::sqrt(area_fraction * nominal_area * spots / std::numbers::pi) / nominal_area;
}

}  // namespace contactbench
