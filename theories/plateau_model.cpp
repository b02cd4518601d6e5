#include "theories/plateau_model.hpp"

#include <cmath>
#include <numbers>

namespace contactbench {

LoadAreaCurve plateau_model(const SweepCurve& sweep) {
  LoadAreaCurve curve;
  curve.method = "plateau";
  curve.parameters =
      describe(sweep.topology) + ", " +
      (sweep.levels.kind == SweepLevels::Kind::exact
           ? std::string("exact levels")
           : std::to_string(sweep.levels.count) +
                 (sweep.levels.kind == SweepLevels::Kind::paper ? " paper levels" : " uniform levels"));
  // Eq. (3) in the dimensionless form P/(E* A0) = (2/sqrt(pi)) sum sqrt(a N / A0) dz, with a = A_c/A0.
  const Real prefactor = 2 / std::sqrt(std::numbers::pi);
  Real load = 0;
  for (std::size_t j = 0; j < sweep.z.size(); ++j) {
    if (j > 0) {
      // On [z[j], z[j-1]) the contact set is the one reported at z[j] (see the header).
      const Real a_times_n = sweep.area_fraction[j] * static_cast<Real>(sweep.spots[j]);
      load += prefactor * std::sqrt(a_times_n / sweep.nominal_area) * (sweep.z[j - 1] - sweep.z[j]);
    }
    curve.separation.push_back(sweep.z[j]);
    curve.load.push_back(load);
    curve.area_fraction.push_back(sweep.area_fraction[j]);
    curve.spots.push_back(static_cast<Real>(sweep.spots[j]));
  }
  return curve;
}

}  // namespace contactbench
