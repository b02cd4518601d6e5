#include "contactbench/bem/solvers/hardness_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactbench {

SolveOutcome search_flat_height(ContactSolver& solver, const HeightMap& heights,
                                const BemSolverOptions& options, Real mean_pressure) {
  constexpr int kMaxTrials = 200;
  const Real hardness = *options.hardness;
  SolveOutcome total;
  total.converged = true;
  int trials = 0;
  // The excess of the capped mean pressure over the load with the flat at d.
  auto excess = [&](Real d) {
    const auto o = solver.solve_separation(d, hardness, options.tolerance, options.max_iterations);
    total.iterations += o.iterations;
    total.change = o.change;
    total.converged = total.converged && o.converged;
    ++trials;
    return solver.mean_pressure() - mean_pressure;
  };
  const Real target = options.tolerance * mean_pressure;
  auto done = [&](Real f) { return std::abs(f) <= target || trials >= kMaxTrials; };
  const Real top = heights.maxCoeff();
  const Real range = std::max(top - heights.minCoeff(), std::numeric_limits<Real>::min());
  // Bracket: d_hi carries at most the load, d_lo at least; steps double from the elastic approach.
  Real d = solver.separation(), f = excess(d);
  Real d_lo = d, f_lo = f, d_hi = d, f_hi = f;
  // First step: the approach times the relative shortfall (a contact's load grows faster than its approach,
  // so this overshoots a little and brackets), then doubling.
  Real step = std::max((top - d) * std::abs(f) / mean_pressure, 1e-6 * range);
  while (!done(f) && f < 0) {
    d_hi = d;
    f_hi = f;
    d -= step;
    step *= 2;
    f = excess(d);
    d_lo = d;
    f_lo = f;
  }
  while (!done(f) && f_hi > 0) {  // not expected (see above), but then search upwards
    d_lo = d;
    f_lo = f;
    d += step;
    step *= 2;
    f = excess(d);
    d_hi = d;
    f_hi = f;
  }
  // Regula falsi with the Illinois modification, bisection when it would leave the bracket; stops at the
  // tolerance on the load, or when the bracket is a rounding error wide.
  int side = 0;
  while (!done(f) && d_hi - d_lo > 4 * std::numeric_limits<Real>::epsilon() * (std::abs(d_lo) + range)) {
    d = d_hi - f_hi * (d_hi - d_lo) / (f_hi - f_lo);
    if (!(d > d_lo && d < d_hi)) d = 0.5 * (d_lo + d_hi);
    f = excess(d);
    if (f >= 0) {  // carries at least the load: the new lower end
      d_lo = d;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      d_hi = d;
      f_hi = f;
      if (side == +1) f_lo *= 0.5;
      side = +1;
    }
  }
  if (std::abs(f) > target) total.converged = false;
  solver.impose_load(mean_pressure, hardness);
  return total;
}

}  // namespace contactbench
