// The exponential-law adhesive contact solved as one bound-constrained minimisation on the whole surface
// (docs/theory.md section 10.11, `adhesive_solver = "projected_lbfgs"`): the total energy per nominal area
//
//     Π(g) = ½ mean((g + h) K (g + h)) + mean(V(g)) [+ (P/A0) mean(g) under load control],   g >= 0,
//
// over the gap g, with K = G⁻¹ the periodic half-space's stiffness ((E*/2)|q|, one FFT pair) and
// V(g) = -w exp(-g/ρ) the law's potential. Its gradient t_el + a(g) + c is the force balance of a point:
// the elastic traction, the attraction and the uniform traction c (the load P/A0, or under separation
// control, where mean(g) = d is held, its multiplier). The method is a projected limited-memory BFGS in the
// spirit of the bound-constrained quasi-Newton minimisation of ContactEngineering's Adhesion package
// (scipy's L-BFGS-B on the same energy); the project's own variant: the bound set frozen per step as in
// Bertsekas' projected Newton method, a backtracking (Armijo) search along the projection arc, and for
// separation control a projection onto {g >= 0, mean(g) = d}. Periodic only: the non-periodic operator has no
// cheap inverse.
#pragma once

#include <memory>
#include <vector>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/adhesion_law.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct LbfgsOutcome {
  Index iterations = 0;   // quasi-Newton steps
  Index evaluations = 0;  // energy-and-gradient evaluations, one FFT pair each
  // max over the points not held at g = 0 of |t + a(g)| / max(w/ρ, max p): the force imbalance, in units of
  // the law's peak stress (or of the largest contact pressure p where that is larger). The fixed point's
  // measure of section 10.3, max |a(g) - a| / (w/ρ), is the same imbalance (its contact solve makes t = -a
  // off contact) in units of the peak.
  Real residual = 0;
  bool converged = false;
  bool separated = false;  // load control: no point within 30 ρ and no contact, the gaps growing
};

class ExponentialLbfgs {
 public:
  // heights: centred, on a periodic grid; modulus E* [Pa]; the law must be exponential.
  ExponentialLbfgs(const Grid& grid, const HeightMap& heights, Real modulus, const AdhesionLaw& law,
                   int threads);
  ~ExponentialLbfgs();

  // load = true: the net mean traction is `value` [Pa]; else the mean gap (the separation) is `value` [m].
  // `gap` is the start (projected onto the feasible set first) and the result. Stops when the residual is at
  // most `tolerance` or after `max_iterations` steps.
  LbfgsOutcome solve(bool load, Real value, Real tolerance, Index max_iterations, HeightMap& gap);

  // Of the last evaluated state: the traction t = K(g + h) + c [Pa] (compressive positive) and c = mean(t).
  const HeightMap& traction() const { return traction_; }
  Real mean_traction() const { return uniform_; }

 private:
  // Π at x, and into gradient_ the force balance K(x + h) + a(x) (without c).
  Real evaluate(const HeightMap& x, bool load, Real pressure);
  // The projection onto {x >= 0} (load) or {x >= 0, mean(x) = d}.
  void project(HeightMap& x, bool load, Real separation) const;

  Grid grid_;
  HeightMap heights_;
  AdhesionLaw law_;
  std::unique_ptr<Convolution<double>> stiffness_;
  HeightMap shifted_, elastic_, gradient_, traction_;
  Real uniform_ = 0;
  int threads_ = 1;  // the element-wise passes' team: the convolution's (one thread on small grids)
};

}  // namespace contactbench
