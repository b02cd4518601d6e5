#include "contactbench/bem/adhesive_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {
// Two states at one separation are the same when their loads differ by less than this fraction of the path's
// load range: far above the solver's tolerance, far below a jump's change of load.
constexpr Real kSameLoad = 1e-3;
// The located pull-off stops when the loads at its bracket's ends are within this fraction of the least load
// found: near a smooth minimum the load's error is quadratic in the separation's, so the least load is then
// within a fraction of that of the true minimum (10x below the 1e-3 the issue asks of the pull-off).
constexpr Real kPullOffLoad = 1e-4;
constexpr int kPullOffSolves = 40;  // a bound; golden sections reach kPullOffLoad in 10 to 20 on a sphere

// The energy a step from `before` to `after` released: the work the load did, by the trapezoid rule, less the
// change of the energy (zero up to the rule's error on a continuous branch; a share of the hysteresis at a
// jump).
Real released_energy(const AdhesivePathState& before, const AdhesivePathState& after) {
  const Real work =
      -0.5 * (before.mean_pressure + after.mean_pressure) * (after.separation - before.separation);
  return work - (after.energy - before.energy);
}

// Golden-section search for the least net load between separations lo < hi on the branch the solver is on
// (its last state at one of them), each solve warm from the last. `inside` is the sampled state between them,
// lower than both ends.
void locate_pull_off(AdhesiveBemSolver& solver, Real lo, Real hi, const AdhesivePathState& inside,
                     AdhesivePath& path) {
  const Real ratio = 0.5 * (std::sqrt(5.0) - 1);
  auto load_at = [&](Real d) {
    ++path.pull_off_solves;
    const AdhesiveSolution& s = solver.solve_for_separation(d);
    path.converged = path.converged && s.converged;
    return s.mean_pressure;
  };
  Real a = lo, b = hi;
  Real x = b - ratio * (b - a), y = a + ratio * (b - a);
  Real fx = load_at(x), fy = load_at(y);
  Real best = std::min({fx, fy, inside.mean_pressure});
  Real best_d = fx <= fy ? x : y;
  if (inside.mean_pressure < best) best_d = inside.separation;
  Real fa = std::numeric_limits<Real>::infinity(), fb = fa;  // the ends' loads are above every inner one
  for (int k = 2; k < kPullOffSolves; ++k) {
    if (fx <= fy) {
      b = y, fb = fy, y = x, fy = fx, x = b - ratio * (b - a), fx = load_at(x);
    } else {
      a = x, fa = fx, x = y, fx = fy, y = a + ratio * (b - a), fy = load_at(y);
    }
    for (const auto& [d, f] : {std::pair{x, fx}, std::pair{y, fy}})
      if (f < best) best = f, best_d = d;
    const Real ends = std::min(fa, fb);
    if (std::isfinite(ends) && ends - best <= kPullOffLoad * std::abs(best)) break;
  }
  path.pull_off_pressure = best;
  path.pull_off_separation = best_d;
  path.pull_off_located = true;
}
}  // namespace

AdhesivePath approach_retract(AdhesiveBemSolver& solver, const AdhesivePathOptions& options) {
  const auto& [start, turn, steps, jump_fraction] = options;
  if (!std::isfinite(start) || !std::isfinite(turn) || !(turn < start) || steps < 2 || !(jump_fraction > 0)) {
    std::ostringstream text;
    text << "adhesive path: needs finite separations with turn < start, steps >= 2 per leg and jump_fraction "
            "> 0; got start "
         << start << ", turn " << turn << ", steps " << steps << ", jump_fraction " << jump_fraction;
    throw Error(text.str());
  }
  if (solver.surface().grid().periodic && !(turn > 0))
    throw Error(
        "adhesive path: on a periodic surface the separation is the mean gap and the path must turn "
        "above 0 m (a mean gap of zero or less needs an infinite load), got turn " +
        std::to_string(turn));
  solver.forget();
  AdhesivePath path;
  path.converged = true;
  const Real step = (start - turn) / static_cast<Real>(steps);
  for (Index k = 0; k <= 2 * steps; ++k) {
    const bool approaching = k <= steps;
    const Real d =
        approaching ? start - step * static_cast<Real>(k) : turn + step * static_cast<Real>(k - steps);
    const AdhesiveSolution& s = solver.solve_for_separation(d);
    AdhesivePathState state{.approaching = approaching,
                            .separation = d,
                            .mean_pressure = s.mean_pressure,
                            .adhesive_pressure = s.adhesive_pressure,
                            .contact_points = s.contact_points,
                            .attractive_points = s.attractive_points,
                            .mean_gap = s.mean_gap,
                            .energy = solver.energy(),
                            .iterations = s.iterations,
                            .converged = s.converged};
    path.converged = path.converged && s.converged;
    if (!approaching && state.mean_pressure < path.pull_off_pressure) {
      path.pull_off_pressure = state.mean_pressure;
      path.pull_off_separation = d;
      path.pull_off_located = false;
    }
    path.states.push_back(state);
    // A bracketed minimum on the retract leg: the state before this one is the least so far and lower than
    // both its neighbours on the leg, with no jump in either step (measured as the jump analysis below
    // does, against the energy range so far: the approach leg has already set it). Located from here, then
    // this state is solved again so that the path goes on from it.
    const std::size_t now = path.states.size() - 1;
    if (approaching || now < static_cast<std::size_t>(steps) + 2) continue;
    const AdhesivePathState &left = path.states[now - 2], &middle = path.states[now - 1],
                            &right = path.states[now];
    if (!middle.approaching && !left.approaching && middle.mean_pressure == path.pull_off_pressure &&
        middle.mean_pressure < left.mean_pressure && middle.mean_pressure < right.mean_pressure) {
      Real lowest = path.states.front().energy, highest = lowest;
      for (const AdhesivePathState& earlier : path.states) {
        lowest = std::min(lowest, earlier.energy);
        highest = std::max(highest, earlier.energy);
      }
      const Real threshold = jump_fraction * (highest - lowest);
      if (released_energy(left, middle) <= threshold && released_energy(middle, right) <= threshold) {
        locate_pull_off(solver, left.separation, right.separation, middle, path);
        solver.solve_for_separation(d);
      }
    }
  }
  // The energy each step released, and the path's energy range (the scale a jump is measured against).
  const std::vector<AdhesivePathState>& states = path.states;
  Real lowest = states.front().energy, highest = lowest;
  std::vector<Real> released(states.size(), 0);
  for (std::size_t k = 1; k < states.size(); ++k) {
    const AdhesivePathState &before = states[k - 1], &after = states[k];
    path.cycle_work +=  // done on the solids
        -0.5 * (before.mean_pressure + after.mean_pressure) * (after.separation - before.separation);
    released[k] = released_energy(before, after);
    lowest = std::min(lowest, after.energy);
    highest = std::max(highest, after.energy);
  }
  // A jump leaves the two legs in different states at the same separation (the hysteresis); a step traversed
  // the same way down and up released nothing, whatever its trapezoid error (a coarse step over a steep
  // rise of the load misjudges the work both ways, with opposite signs). The legs share their separations:
  // state k of the approach and state 2 steps - k of the retract.
  Real least_load = 0, most_load = 0;
  for (const AdhesivePathState& s : states) {
    least_load = std::min(least_load, s.mean_pressure);
    most_load = std::max(most_load, s.mean_pressure);
  }
  const std::size_t last = states.size() - 1;
  const auto legs_differ = [&](std::size_t k) {
    return std::abs(states[k].mean_pressure - states[last - k].mean_pressure) >
           kSameLoad * (most_load - least_load);
  };
  for (std::size_t k = 1; k < states.size(); ++k) {
    if (!(released[k] > jump_fraction * (highest - lowest))) continue;
    if (!legs_differ(k - 1) && !legs_differ(k)) continue;
    const AdhesivePathState &before = states[k - 1], &after = states[k];
    path.jumps.push_back({.into_contact = after.approaching,
                          .after = static_cast<Index>(k),
                          .separation_before = before.separation,
                          .separation_after = after.separation,
                          .mean_pressure_before = before.mean_pressure,
                          .mean_pressure_after = after.mean_pressure,
                          .contact_points_before = before.contact_points,
                          .contact_points_after = after.contact_points,
                          .released_energy = released[k]});
    path.released_energy += released[k];
  }
  return path;
}

}  // namespace contactbench
