// The solver "polonsky_keer": Polonsky & Keer's constrained conjugate gradient (Wear 231, 206-219, 1999;
// docs/theory.md section 6, docs/solvers.md), the search direction built from the gap on the contact set.
// Its loop also serves "preconditioned_cg" (preconditioned_cg_solver.hpp), which changes the direction under
// load control only. Internal to the solvers (bem/solvers/); callers use BemSolver.
#pragma once

#include <memory>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/bem/solvers/constrained_cg_kernels.hpp"
#include "contactbench/bem/solvers/pressure_state.hpp"

namespace contactbench {

// The iteration in scalar T (double, or float for large grids), keeping its state between solves.
//
// The pressure is kept as p = s q: q an array, s a scalar. Under load control the load is imposed by
// rescaling (PK's step), and as the operator is linear, G p = s G q: the rescaling is never a pass over the
// arrays. Two arrays q alternate, so that the change of the pressure in an iteration can be measured while
// the next gap is computed. The sets are read off q: elastic contact where 0 < p < H (the conjugate
// gradient's set), plastic where p = H (with a hardness), out of contact where p = 0. Every element-wise
// step rides inside a convolution (bem/convolution.hpp); one iteration is
//   G t: producing t (direction) | consuming r = G t (its sum on the contact set; load control only)
//   G q: producing q (the update) | consuming u = G q (gap, its moments, the change of the pressure)
// and the apply that finishes an iteration is the one that starts the next: the same count of operator
// applications as PK's loop (two per iteration and one to start), and no other pass over the arrays.
template <class T>
class PolonskyKeerSolver : public PressureState<T> {
 public:
  PolonskyKeerSolver(const Surface& centred, Real modulus, int threads);

  SolveOutcome solve_load(double mean_pressure, double hardness, double tolerance, Index max_iterations,
                          bool extrapolate) override;
  bool caps_load_control() const override { return false; }
  SolveOutcome solve_separation(double separation, double hardness, double tolerance,
                                Index max_iterations) override;
  void impose_load(double mean_pressure, double hardness) override;

 protected:
  using Producer = typename Convolution<T>::Producer;
  using Consumer = typename Convolution<T>::Consumer;
  using Hook = typename Convolution<T>::Hook;

  // What the passes of one iteration read: the pressure p = s q, the gap's mean on the elastic set, the
  // conjugation's beta, and (preconditioned) the filtered residual's mean.
  struct Pass {
    const T* q = nullptr;
    T s = 0, gbar = 0, zbar = 0, beta = 0;
  };
  // Of the filter pass (preconditioned): sums r z, z and r over the elastic set.
  struct FilterSums {
    double rz = 0, z_sum = 0, r_sum = 0;
  };

  // The preconditioned direction (PreconditionedCgSolver) replaces PK's under load control when this is true.
  virtual bool preconditions() const { return false; }
  // Preconditioned: z, the filtered residual on the elastic set; returns the sums over it.
  virtual FilterSums filter_residual(const Pass&) { return {}; }
  // Preconditioned: the direction t = (z - zbar) + beta t into G, `response` consuming G t; returns <t, G t>.
  virtual double preconditioned_direction(const Pass&, Consumer) { return 0; }

  void clear_partials() {
    for (cg::Partial& part : partial_)
      part.clear();
  }

  std::unique_ptr<Convolution<T>> convolution_;
  std::vector<T> t_;
  std::vector<cg::Partial> partial_;

 private:
  template <bool kLoad, bool kHard>
  SolveOutcome iterate(double total, double tolerance, Index max_iterations);
};

extern template class PolonskyKeerSolver<double>;
extern template class PolonskyKeerSolver<float>;

// The registry's entry (bem/solver_registry.cpp).
SolverEntry polonsky_keer_entry();

}  // namespace contactbench
