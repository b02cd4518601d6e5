// The solver "active_set" (bem/solver_registry.hpp): a primal-dual active-set (semismooth Newton) method for
// the contact problem of bem/bem_solver.hpp, under load or separation control, elastic or capped at a
// hardness: the linear problem on a guessed contact set solved by a conjugate gradient with the extended
// Fourier filter, the set updated from p and the gap, from a nested coarse start. What it does, its
// convergence test and how its iterations are counted: docs/solvers.md "The active-set method" and "The
// active-set method, precisely"; the code in bem/solvers/active_set_*.
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct ActiveSetOutcome {
  Index iterations =
      0;  // inner CG iterations + outer steps + coarse levels (docs/solvers.md): `work` rounded
  Index coarse_iterations = 0;  // of the coarse levels, as they counted (each costs 1/4 of the finer's)
  double work = 0;              // the same in fine-grid iterations, the coarse levels' quarters not rounded
  Index outer = 0;
  double residual = 0;      // max |g| on the contact set / height range
  double change = 0;        // sum |p - p_before| / sum p over the last outer step
  double separation = 0;    // the flat's height d (g = d - h + G p)
  double pressure_sum = 0;  // sum p over the nodes [Pa]
  bool converged = false;
};

// What a solve imposes: the load (the flat's height found) or the flat's height (the load found), and the
// pressure cap (infinite: elastic).
struct ActiveSetProblem {
  bool load_control = true;
  double mean_pressure = 0;                                   // [Pa], load control
  double separation = 0;                                      // the flat's height d [m], separation control
  double hardness = std::numeric_limits<double>::infinity();  // [Pa]
};

// The solver on `grid` (heights centred, row-major ny x nx), keeping its FFT plans, arrays and coarse
// levels from solve to solve (bem/solvers/active_set_method.hpp).
template <class T>
class ActiveSetSolver {
 public:
  ActiveSetSolver(const Grid& grid, std::vector<T> heights, Real modulus, int threads);
  ~ActiveSetSolver();
  ActiveSetSolver(const ActiveSetSolver&) = delete;
  ActiveSetSolver& operator=(const ActiveSetSolver&) = delete;

  // Solves `problem`. `pressure`: in, the start when `warm` (under load control scaled to the load), else
  // ignored and a nested coarse start is made; out, the solution. `displacement_minus_heights`: out,
  // G p - h (the gap less the flat's height). `between` is called before every inner iteration (may be
  // empty; may throw).
  ActiveSetOutcome solve(const ActiveSetProblem& problem, double tolerance, Index max_iterations, bool warm,
                         std::vector<T>& pressure, std::vector<T>& displacement_minus_heights,
                         const std::function<void()>& between);
  // Replaces the heights the next solves press against (the adhesive solver's outer iterations; the
  // coarse levels of the nested start follow).
  void set_heights(const std::vector<T>& heights);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contactbench
