#include "contactbench/bem/adhesive_path.hpp"

#include <cmath>
#include <sstream>

#include "contactbench/core/error.hpp"

namespace contactbench {

AdhesivePath approach_retract(AdhesiveBemSolver& solver, const AdhesivePathOptions& options) {
  const auto& [start, turn, steps, jump_fraction, jump_floor] = options;
  if (!std::isfinite(start) || !std::isfinite(turn) || !(turn < start) || steps < 2 || !(jump_fraction > 0) ||
      !(jump_floor >= 0)) {
    std::ostringstream text;
    text
        << "adhesive path: needs finite separations with turn < start, steps >= 2 per leg, jump_fraction > 0 "
           "and jump_floor >= 0; got start "
        << start << ", turn " << turn << ", steps " << steps;
    throw Error(text.str());
  }
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
    if (k > 0) {
      const AdhesivePathState& before = path.states.back();
      const Real move = d - before.separation;
      const Real work = -0.5 * (before.mean_pressure + state.mean_pressure) * move;  // done on the solids
      path.cycle_work += work;
      const Real released = work - (state.energy - before.energy);
      if (released > jump_fraction * std::abs(work) && released > jump_floor) {
        path.jumps.push_back({.into_contact = approaching,
                              .after = k,
                              .separation_before = before.separation,
                              .separation_after = d,
                              .mean_pressure_before = before.mean_pressure,
                              .mean_pressure_after = state.mean_pressure,
                              .contact_points_before = before.contact_points,
                              .contact_points_after = state.contact_points,
                              .released_energy = released});
        path.released_energy += released;
      }
    }
    path.states.push_back(state);
  }
  return path;
}

}  // namespace contactbench
