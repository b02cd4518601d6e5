#include "contactbench/bem/solvers/hardness_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contactbench {

SolveOutcome search_flat_height(ContactSolver& solver, const HeightMap& heights,
                                const BemSolverOptions& options, Real mean_pressure, FlatHeightMemory& memory,
                                bool from_memory) {
  constexpr int kMaxTrials = 200;
  const Real hardness = *options.hardness;
  SolveOutcome total;
  total.converged = true;
  int trials = 0;
  // Inexact trials: a trial far from the load needs its mean pressure only well enough to trust the sign and
  // size of its excess f over the load. A trial is solved to 1/kTrust of the last trial's relative excess
  // |f|/P (never tighter than the tolerance, never looser than kLoosestTrial), and its own f is trusted only
  // when |f|/P is at least kTrust times the tolerance it was solved to; otherwise it is solved again, warm,
  // to 1/kTrust of its |f|/P. So a trial that meets the load is one solved at the tolerance, as before.
  // Measured on surface A at 256^2 (docs/solvers.md "Hardness", cost): a trial's mean pressure was off by up
  // to 1.5 times its tolerance, hence a factor 100; most of the exact search's iterations went into trials
  // that the next one discarded.
  constexpr Real kTrust = 100;
  constexpr Real kLoosestTrial = 1e-4;
  const Real loosest = std::max(kLoosestTrial, options.tolerance);
  Real trial_tolerance = loosest;
  Real solved_at = 0;  // the tolerance of the last trial
  // The last two trials, for the stiffness the next search starts from.
  Real last_d = 0, last_f = 0, before_d = 0, before_f = 0;
  // The excess of the capped mean pressure over the load with the flat at d.
  auto excess = [&](Real d) {
    Real f = 0;
    for (;;) {
      const auto o = solver.solve_separation(d, hardness, trial_tolerance, options.max_iterations);
      total.iterations += o.iterations;
      total.change = o.change;
      total.converged = total.converged && o.converged;
      solved_at = trial_tolerance;
      ++trials;
      f = solver.mean_pressure() - mean_pressure;
      const Real relative = std::abs(f) / mean_pressure;
      if (trial_tolerance <= options.tolerance || relative >= kTrust * trial_tolerance) break;
      trial_tolerance = std::max(options.tolerance, 0.5 * relative / kTrust);  // 0.5: at least halved
    }
    trial_tolerance = std::clamp(std::abs(f) / mean_pressure / kTrust, options.tolerance, loosest);
    if (d != last_d) {  // a trial at a new height (the last one may be solved again at the tolerance)
      before_d = last_d;
      before_f = last_f;
    }
    last_d = d;
    last_f = f;
    return f;
  };
  const Real target = options.tolerance * mean_pressure;
  auto done = [&](Real f) { return std::abs(f) <= target || trials >= kMaxTrials; };
  const Real top = heights.maxCoeff();
  const Real range = std::max(top - heights.minCoeff(), std::numeric_limits<Real>::min());
  // Bracket: d_hi carries at most the load, d_lo at least; steps double from the first.
  const bool remembered = memory.stiffness > 0 && std::isfinite(memory.stiffness);
  // From the last search: the load taken as locally exponential in the flat's height, P ~ exp(-d / lambda)
  // with lambda = P / k (as a rough contact's is, Persson 2007; docs/theory.md section 6.7): on surface A at
  // 256^2 (loads 0.001 to 0.01 of E* in steps of 0.001) its first trial was within 0.4 % of the load where a
  // straight line through the last stiffness was 3 to 10 % off, and the elastic solve it replaces about 1 %.
  Real d = solver.separation();
  if (from_memory && remembered)
    d = memory.separation -
        memory.mean_pressure / memory.stiffness * std::log(mean_pressure / memory.mean_pressure);
  Real f = excess(d);
  Real d_lo = d, f_lo = f, d_hi = d, f_hi = f;
  // First step: with the last search's stiffness, a Newton step; without, the approach times the relative
  // shortfall (a contact's load grows faster than its approach, so this overshoots a little and brackets).
  // Then doubling.
  Real step = remembered ? std::abs(f) / memory.stiffness
                         : std::max((top - d) * std::abs(f) / mean_pressure, 1e-6 * range);
  step = std::max(step, 1e-9 * range);
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
  if (solved_at > options.tolerance) {  // stopped on the bracket's width after a looser trial
    trial_tolerance = options.tolerance;
    f = excess(d);
  }
  if (std::abs(f) > target) total.converged = false;
  solver.impose_load(mean_pressure, hardness);
  const Real secant = (before_f - last_f) / (last_d - before_d);  // -dP/dd of the last two trials
  memory = {.mean_pressure = mean_pressure,
            .separation = d,
            .stiffness = trials >= 2 && std::isfinite(secant) && secant > 0 ? secant : 0};
  return total;
}

}  // namespace contactbench
