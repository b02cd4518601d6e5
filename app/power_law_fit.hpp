// The power law n(s) = c s^(-tau) of a patch-size number density on log-log axes (docs/theory.md section
// 12.8): a least-squares line through (ln s, ln n) over the bins of a chosen range, its slope -tau.
#pragma once

#include <string>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

struct PowerLawFit {
  bool fitted = false;  // false: fewer than 3 bins in the range (`reason` says so)
  Real exponent = 0;    // tau, n ~ s^(-tau)
  Real prefactor = 0;   // c
  Real low = 0;         // the range fitted: the smallest and largest bin centre used
  Real high = 0;
  Index bins = 0;      // bins used
  std::string reason;  // why not fitted
};

// Over the bins i with centre[i] >= min_size and counts[i] >= min_count (both > 0 then), the unweighted
// least-squares fit of ln density[i] = ln c - tau ln centre[i]. The vectors have one entry per bin.
PowerLawFit fit_power_law(const std::vector<Real>& centre, const std::vector<Real>& density,
                          const std::vector<Index>& counts, Real min_size, Index min_count);

}  // namespace contactbench
