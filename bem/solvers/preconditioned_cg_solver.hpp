// The solver "preconditioned_cg" (docs/solvers.md): Polonsky & Keer's loop (polonsky_keer_solver.hpp) with
// the gap residual (its mean on the contact set removed) filtered by (E*/2)|q| in Fourier space
// (bem/fourier_preconditioner.hpp), restricted to the contact set again with its mean there removed, before
// it becomes a direction. Conjugation restarts when nodes enter the set, entering nodes take the overlap
// times the plain step <t,t>/<t,Gt> (PolonskyKeerStep::lengths), and convergence also asks that no node
// entered or left the set in the last update. Load control only: under separation control, and so with a
// hardness, it iterates as polonsky_keer. Internal to the solvers (bem/solvers/); callers use BemSolver.
#pragma once

#include "contactbench/bem/solvers/polonsky_keer_solver.hpp"

namespace contactbench {

template <class T>
class PreconditionedCgSolver final : public PolonskyKeerSolver<T> {
 public:
  PreconditionedCgSolver(const Surface& centred, Real modulus, int threads);

 private:
  using typename PolonskyKeerSolver<T>::Pass;
  using typename PolonskyKeerSolver<T>::FilterSums;
  using typename PolonskyKeerSolver<T>::Producer;
  using typename PolonskyKeerSolver<T>::Consumer;
  using typename PolonskyKeerSolver<T>::Hook;

  bool preconditions() const override { return true; }
  FilterSums filter_residual(const Pass& pass) override;
  double preconditioned_direction(const Pass& pass, Consumer response) override;

  std::unique_ptr<Convolution<T>> preconditioner_;
  std::vector<T> z_;  // the filtered residual on the elastic set
};

extern template class PreconditionedCgSolver<double>;
extern template class PreconditionedCgSolver<float>;

// The registry's entry (bem/solver_registry.cpp).
SolverEntry preconditioned_cg_entry();

}  // namespace contactbench
