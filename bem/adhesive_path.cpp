#include "contactbench/bem/adhesive_path.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {
// Two states at one separation are the same when their loads differ by less than this fraction of the path's
// load range: far above the solver's tolerance, far below a jump's change of load.
constexpr Real kSameLoad = 1e-3;
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
    }
    path.states.push_back(state);
  }
  // The energy each step released, and the path's energy range (the scale a jump is measured against).
  const std::vector<AdhesivePathState>& states = path.states;
  Real lowest = states.front().energy, highest = lowest;
  std::vector<Real> released(states.size(), 0);
  for (std::size_t k = 1; k < states.size(); ++k) {
    const AdhesivePathState &before = states[k - 1], &after = states[k];
    const Real work =
        -0.5 * (before.mean_pressure + after.mean_pressure) * (after.separation - before.separation);
    path.cycle_work += work;  // done on the solids
    released[k] = work - (after.energy - before.energy);
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
