#include "contactbench/theories/summit_gap_density.hpp"

#include <cmath>
#include <numbers>

#include "contactbench/theories/greenwood_williamson.hpp"

namespace contactbench {

SummitGap summit_gap_at_load(const SpectralMoments& moments, Real load) {
  const GwParameters gw = mccool_parameters(moments);
  return {.separation = gw_separation(gw, gw_solve_separation(gw, load)), .rms_height = moments.rms_height()};
}

Real summit_gap_density(const SummitGap& summit, Real gap) {
  if (gap < 0) return 0;
  const Real x = (summit.separation - gap) / summit.rms_height;
  return std::exp(-x * x / 2) / (std::sqrt(2 * std::numbers::pi) * summit.rms_height);
}

}  // namespace contactbench
