// The one interface every BEM solver implements (bem/solver_registry.hpp lists them; docs/solvers.md says
// what each does). BemSolver (bem/bem_solver.hpp) holds one, made by the registry's factory, and adds
// what is the same for every solver: the checks of the input, the zero load, the coarse start
// (bem/solvers/load_stepping.hpp), the search on the flat's height that meets a hardness under load control
// for the solvers that do not meet it themselves (bem/solvers/hardness_search.hpp) and the solution's
// converged flag.
#pragma once

#include <functional>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// What a solve reports besides the fields.
struct SolveOutcome {
  Index iterations = 0;
  double change = 0;
  bool converged = false;
};

class ContactSolver {
 public:
  virtual ~ContactSolver() = default;
  // The next solve starts afresh (after an abandoned solve, or a zero load).
  virtual void forget() = 0;
  // Called before every iteration (BemSolverOptions::between_iterations; may be empty, may throw).
  void set_between_iterations(std::function<void()> hook) { between_iterations_ = std::move(hook); }
  // Replaces the heights (ny x nx) the next solves press against, keeping the last pressure as the warm
  // start: the adhesive solver (bem/adhesive_solver.hpp) presses the contact against the heights less the
  // displacement of the attraction, which changes between its outer iterations.
  virtual void set_heights(const HeightMap& heights) = 0;
  // Whether a solve would start from a previous solution.
  virtual bool warm() const = 0;
  // The next solve starts from this pressure [Pa] (ny x nx), as from a previous solution.
  virtual void start_from(const HeightMap& pressure) = 0;
  // Load control: mean(p) = mean_pressure, the flat's height found; pressures capped at `hardness` (may be
  // infinite) when caps_load_control(), else elastic (BemSolver::solve then meets the cap by a search on
  // the flat's height, bem/solvers/hardness_search.hpp). extrapolate: start from the linear extrapolation of
  // the last two load-controlled solutions (when there are two), else from the last one scaled to the load.
  virtual SolveOutcome solve_load(double mean_pressure, double hardness, double tolerance,
                                  Index max_iterations, bool extrapolate) = 0;
  // Whether solve_load meets a hardness itself (active_set's plastic set) rather than solving elastically.
  virtual bool caps_load_control() const = 0;
  // Separation control: the flat at `separation`, the load found; pressures capped at `hardness` (may be
  // infinite).
  virtual SolveOutcome solve_separation(double separation, double hardness, double tolerance,
                                        Index max_iterations) = 0;
  // Rescales the elastic part of the pressure so that the mean is mean_pressure exactly (plastic nodes stay
  // at the hardness), and finds the flat's height and the gap of the result as load control does.
  virtual void impose_load(double mean_pressure, double hardness) = 0;
  // Writes the last solution (pressure, gap, separation, counts, residual); returns the mean pressure.
  virtual double write(ContactSolution& s) const = 0;
  virtual double max_pressure() const = 0;
  // Of the last solve: the flat's height, and the mean pressure (sum p / points).
  virtual double separation() const = 0;
  virtual double mean_pressure() const = 0;

 protected:
  std::function<void()> between_iterations_;
};

}  // namespace contactbench
