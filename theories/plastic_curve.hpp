// What every elastic-plastic theory answers besides its load-area curve (docs/theory.md section 11): the
// share of the nominal area in plastic contact and the share of the load it carries, and the check every such
// theory makes of its hardness.
#pragma once

#include <limits>
#include <span>
#include <string_view>
#include <vector>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// The hardness of a theory that runs without one: every contact stays elastic.
inline constexpr Real kNoHardness = std::numeric_limits<Real>::infinity();

struct PlasticCurve {
  LoadAreaCurve curve;                      // A/A0 is the whole contact area, elastic and plastic
  std::vector<Real> plastic_area_fraction;  // A_plastic/A0, per load (the BEM's plastic nodes / all nodes)
  std::vector<Real> plastic_load_fraction;  // P_plastic/P, per load
};

// Refuses (Error naming `method`, each such load and its position) a dimensionless hardness H/E* that is not
// > 0 (infinity, kNoHardness, is accepted: elastic), or that is at or below a load P/(E* A0): the mean
// pressure P/A0 would reach H, which is full plastic contact (A = A0) and beyond.
void check_hardness(Real hardness_over_estar, std::span<const Real> loads, std::string_view method);

}  // namespace contactbench
