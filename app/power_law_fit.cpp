#include "contactbench/app/power_law_fit.hpp"

#include <cmath>

namespace contactbench {

PowerLawFit fit_power_law(const std::vector<Real>& centre, const std::vector<Real>& density,
                          const std::vector<Index>& counts, Real min_size, Index min_count) {
  PowerLawFit fit;
  Real sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < centre.size(); ++i) {
    if (centre[i] < min_size || counts[i] < min_count || !(density[i] > 0)) continue;
    const Real x = std::log(centre[i]), y = std::log(density[i]);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    if (fit.bins == 0) fit.low = centre[i];
    fit.high = centre[i];
    ++fit.bins;
  }
  if (fit.bins < 3) {
    fit.reason = "fewer than 3 bins with size >= " + std::to_string(min_size) + " and at least " +
                 std::to_string(min_count) + " patches";
    return fit;
  }
  const Real n = static_cast<Real>(fit.bins);
  const Real slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  fit.fitted = true;
  fit.exponent = -slope;
  fit.prefactor = std::exp((sy - slope * sx) / n);
  return fit;
}

}  // namespace contactbench
