// The contact stiffness per unit area of a converged boundary-element state, K = -dP/dd, from its
// linearised response (docs/theory.md section 12.2): held on its elastic contact set C (0 < p, and p < H
// with a hardness: plastic points carry a fixed pressure), the surface moved towards the flat by a uniform
// delta needs the extra pressure x delta, where G x = 1 on C and x = 0 elsewhere; then K = mean(x) over the
// nominal area. G restricted to C is symmetric positive definite (the periodic operator's one null mode, the
// uniform field, is not supported on a proper subset of the grid), so conjugate gradients solve it.
//
// d is the flat's rigid approach (BemSolver's separation, with the sign of an approach). On a periodic grid
// the mean gap is d itself (the operator has no mean displacement), so K = -dP/du-bar too; on a
// non-periodic patch the mean gap moves with the far-field displacement as well, and K is -dP/dd only.
//
// K is read from the CG iterate x by the variational (energy) estimate K = (2 1.x - x.Gx) / N, which equals
// (1.x + x.r) / N with r = 1 - Gx on C: its error is -(r.G^-1 r) / N, quadratic in the residual
// (docs/theory.md 12.2), so a residual of 1e-5 already gives K to about 1e-10 relative.
#pragma once

#include <memory>
#include <optional>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct ContactStiffness {
  Real stiffness = 0;      // K [Pa/m]; +inf on a periodic grid in full contact; 0 without contact
  Index iterations = 0;    // of conjugate gradients
  Real residual = 0;       // |G x - 1| / |1| on C at the end
  bool converged = false;  // residual <= the tolerance asked
};

// The relative residual the load-path stages solve to (app/serial_runner.cpp): the energy estimate's error
// is quadratic in it, and measured on surface A 512^2 at the paper scene's 12 loads the stiffness then
// agrees with that of a 1e-10 solve to 1.3e-10 relative at most (bench/bench_contact_stiffness.cpp;
// docs/solvers.md, "The stiffness solve"), far below the 1e-4 the comparison needs.
inline constexpr Real kStageStiffnessTolerance = 1e-5;

struct StiffnessOptions {
  Real tolerance = 1e-10;       // relative residual |G x - 1| / |1| on C
  Index max_iterations = 5000;  // of conjugate gradients
};

// The stiffness solves of one stage: the operator and the preconditioner are planned once, for every load
// on `grid`. Each solve starts from x = 0: a start from the last load's response, restricted to the new set
// and scaled, was measured to save nothing (docs/solvers.md, "The stiffness solve").
class ContactStiffnessSolver {
 public:
  // `grid` (its periodicity chooses the operator), modulus E* [Pa]; `hardness` [Pa] when the states are
  // capped.
  ContactStiffnessSolver(const Grid& grid, Real modulus, std::optional<Real> hardness = std::nullopt,
                         int threads = 1, StiffnessOptions options = {});
  ~ContactStiffnessSolver();
  ContactStiffnessSolver(const ContactStiffnessSolver&) = delete;
  ContactStiffnessSolver& operator=(const ContactStiffnessSolver&) = delete;

  // The stiffness of the state with this `pressure` [Pa] on the solver's grid.
  ContactStiffness solve(const HeightMap& pressure);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One state alone, from x = 0: `pressure` [Pa] on `grid`, modulus E* [Pa]; `hardness` [Pa] when the state was
// capped. Solves to the relative residual `tolerance` in at most `max_iterations`.
ContactStiffness contact_stiffness(const Grid& grid, Real modulus, const HeightMap& pressure,
                                   std::optional<Real> hardness = std::nullopt, int threads = 1,
                                   Real tolerance = 1e-10, Index max_iterations = 5000);

}  // namespace contactbench
