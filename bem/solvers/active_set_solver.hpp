// The solver "active_set" behind the solver interface: the primal-dual active-set method of
// bem/active_set.hpp (docs/solvers.md) with the pressure, gap and warm starts every solver keeps
// (pressure_state.hpp). It meets a hardness itself, under load or separation control. Internal to the
// solvers (bem/solvers/); callers use BemSolver.
#pragma once

#include <memory>

#include "contactbench/bem/active_set.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/bem/solvers/pressure_state.hpp"

namespace contactbench {

template <class T>
class ActiveSetContactSolver final : public PressureState<T> {
 public:
  ActiveSetContactSolver(const Surface& centred, Real modulus, int threads);

  SolveOutcome solve_load(double mean_pressure, double hardness, double tolerance, Index max_iterations,
                          bool extrapolate) override;
  bool caps_load_control() const override { return true; }
  SolveOutcome solve_separation(double separation, double hardness, double tolerance,
                                Index max_iterations) override;
  // The method's own copy and its coarse levels follow.
  void set_heights(const HeightMap& heights) override;
  // Never needed: a capped load is one solve (caps_load_control).
  void impose_load(double mean_pressure, double hardness) override;

 private:
  // From the start solve_load made or the last solution (when warm), else from the method's own nested
  // coarse start; leaves the state as the other solvers do.
  SolveOutcome solve(const ActiveSetProblem& problem, double tolerance, Index max_iterations);

  ActiveSetSolver<T> method_;
};

extern template class ActiveSetContactSolver<double>;
extern template class ActiveSetContactSolver<float>;

// The registry's entry (bem/solver_registry.cpp).
SolverEntry active_set_entry();

}  // namespace contactbench
