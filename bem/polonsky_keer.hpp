// The boundary-element ground truth: frictionless normal contact of a rough rigid surface and an elastic
// half-space (equivalently a rigid flat on a rough elastic body), solved for a prescribed mean pressure by
// the constrained conjugate gradient of Polonsky & Keer (Wear 231, 206-219, 1999; docs/theory.md section 6),
// or its Fourier-preconditioned variant (below; docs/solvers.md).
//
// Unknowns: the pressure p >= 0 on the grid and the flat's height d above the mean plane. The gap is
// g = d - h + u(p) >= 0 with u = G p the elastic displacement (bem/half_space.hpp); where p > 0 the gap is 0,
// and mean(p) = the prescribed mean pressure. Each iteration costs two applications of G (two FFT pairs),
// with all of its element-wise work fused into them (bem/convolution.hpp): about two FFT pairs in all.
//
// Three iterations solve this problem (options.solver, bem/solver_registry.hpp; docs/solvers.md):
// - polonsky_keer: PK's constrained CG, the search direction built from the gap on the contact set;
// - preconditioned_cg: the same loop with the gap residual (its mean on the contact set removed) filtered by
//   (E*/2)|q| in Fourier space (bem/fourier_preconditioner.hpp), restricted to the contact set again with its
//   mean there removed, before it becomes a direction; conjugation restarts when nodes enter the set, and
//   entering nodes take the overlap times the plain step <t,t>/<t,Gt> (PK's entry step has the wrong
//   dimension once t is a pressure). One more convolution an iteration (periodic: one FFT pair; non-periodic:
//   3/4 of a padded pair, as the operator's), far fewer iterations, and a count that grows much more slowly
//   with the grid (results/bench/bem_solvers.md);
// - active_set: a primal-dual active-set method (bem/active_set.hpp): the linear problem on a guessed contact
//   set solved by a conjugate gradient with the same filter, the set updated from p and the gap, from a
//   nested coarse start; a count that barely grows with the grid. It stops on its own criterion (the set
//   settled, the largest gap on it at most the tolerance times the approach max h - d, the last CG step's
//   relative change at most the tolerance; bem/active_set.hpp). The default (kDefaultSolver): the fastest
//   of the three along the load curves scenes run, from 256^2 to 1024^2 (docs/solvers.md).
//
// active_set solves every problem itself: load or separation control, elastic or capped at a hardness (a
// third, plastic set; a capped load is one solve). preconditioned_cg applies to load-controlled elastic
// solves; under separation control and with a hardness it iterates as polonsky_keer (polonsky_keer.cpp says
// why), and with both of them a capped load is met by a search on the flat's height, each trial a capped
// solve under separation control.
//
// Stopping criteria of polonsky_keer and preconditioned_cg, the same tolerance for both (active_set: above):
// - the relative change of the pressure in one iteration (Polonsky & Keer's),
//     sum |p_new - p_old| / sum p_new < tolerance;
// - and, for every solver, the complementarity residual at most residual_bound(tolerance) (below): a solve
//   that met the change criterion with a larger residual is marked converged = false, with a warning;
// - preconditioned_cg also requires that no node entered or left the contact set in that iteration: the
//   change is then a CG step on a settled set, which is why it cannot stall on a wrong answer (the failure
//   of preconditioning the whole gap: a change of 1e-16 with the pressure 100 % off). Its direction is a
//   descent direction of the constrained problem whenever the gap on the contact set is not uniform
//   (<r, z> > 0 for the positive filter), so a vanishing step means a vanishing residual.
// The complementarity residual is reported as `residual`: the largest |g| on the contact set relative to
// the surface's height range. What the tolerance buys (measured by bench/bench_bem_solvers.cpp against a
// solve at 1e-12 on surface A and an H = 0.8 surface, 256^2 to 2048^2, 1 % to 30 % contact): the contact
// area to 1e-4 relative and the pressure to 1e-4 relative L2 needed a tolerance of 1e-4 to 1e-6 with
// polonsky_keer, twice 1e-7, and 1e-3 to 1e-5 with preconditioned_cg, once 1e-7 (where 1e-4 of the area is
// about one node: the count must be exact), and 1e-4 to 1e-6 with active_set (1e-5 in 29 of 45 cases, 1e-6
// in 3); results/bench/bem_solvers.md, column tol. The defaults (1e-10 here, 1e-8 in scenes and
// on the command line) are tighter than that for all three. A solve
// that reaches the iteration cap is marked converged = false and says so through the options' warning sink;
// it is never passed off as converged.
//
// Hardness (optional): a perfectly plastic cap, p <= H. Nodes at p = H are plastic: their gap may be negative
// (the surface there flowed; the overlap is the plastic indentation) and they leave the conjugate-gradient
// set, which is the elastic contact {0 < p < H}; a plastic node whose gap opens (g > 0) is released, as a
// node out of contact that the surface penetrates enters (the standard capped PK variant: e.g. Almqvist et
// al., Tribol. Int. 40, 2007; Weber et al., Nat. Commun. 9, 2018). Rescaling the pressure to the load, PK's
// way of imposing it, does not commute with the cap, so under load control the cap is met the way a
// rigid-body approach is: the capped problem is solved for the flat's height d (separation control, where
// the CG needs neither the mean taken out nor the rescaling, and the cap is a plain projection onto
// [0, H]), and d is searched (bracketed, then regula falsi with the Illinois modification) until the mean
// pressure is the load to the relative tolerance; the elastic pressures are then rescaled to impose it
// exactly. The search starts from the elastic solution, which is the answer when its largest pressure is at
// most H (then no capped code runs at all). Without a hardness, nothing of this runs.
//
// Separation control (solve_for_separation): the flat's height d above the mean plane of the heights is
// imposed and the load is the unknown; the CG then takes no mean out of the gap and does not rescale the
// pressure (PK's two steps for an unknown d and a known load). Why d and not the mean gap: in the periodic
// case they are the same thing (the operator's q = 0 mode is zero, so the displacement has zero mean and
// the mean gap is d - mean(h) + mean(u) = d), and there d must be > 0 (a mean gap of zero or less needs an
// infinite load; refused, unless a hardness bounds the load); in the non-periodic case d is the rigid-body
// approach measured from the undeformed surface (the displacement vanishes far away; the approach of the
// highest point is max h - d, Hertz's and Sneddon's delta), while the mean gap over the window would
// depend on the displacement of the whole window, a poor thing to prescribe. Solving for the d that a
// load-controlled solve reported gives that load back (tests/test_bem_effects.cpp).
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

enum class LoadPathStart { scaled, extrapolated };

struct PolonskyKeerOptions {
  Real tolerance = 1e-10;  // on the relative change of the pressure (see above)
  Index max_iterations = 20000;
  // The indentation hardness H [Pa] of a perfectly plastic cap p <= H (see above); none: purely elastic.
  // A mean pressure P/A0 >= H is refused: the whole surface would be plastic (full plastic contact, p = H
  // everywhere, the flat's height undetermined).
  std::optional<Real> hardness = std::nullopt;
  // Iterate in single precision (FFTW's float transforms, float arrays; sums still in double): half the
  // memory, and faster (measured per iteration, one thread: x1.2 at 256^2, x1.5 to x1.6 at 1024^2). Float
  // resolves a relative change of about 1e-7 (its epsilon) and the gap g = u - h to about 1e-7 of the
  // heights, so a tolerance below kSinglePrecisionTolerance is refused. Results agree with double precision
  // to float's accuracy (e.g. the area fraction to 1e-3 relative, the mean gap to 1e-4;
  // tests/test_bem_effects.cpp).
  bool single_precision = false;
  // Where a warning goes (a solve that reached the iteration cap): the application's sink; none, silent (the
  // solution still says converged = false). The library never writes to a stream itself.
  std::function<void(const std::string&)> warning = nullptr;
  // Which iteration (bem/solver_registry.hpp, docs/solvers.md): Polonsky & Keer's, the same with the
  // Fourier-preconditioned direction, or the active-set method. Same problem, same options, converged means
  // the residual check passed for each.
  SolverKind solver = kDefaultSolver;
  // Where solve() starts a load after a previous one (load stepping, loads in increasing order):
  // scaled, the last solution scaled to the new load; extrapolated, the linear extrapolation of the last two
  // solutions in the load (clipped at 0, then scaled), the last one scaled when there is only one.
  LoadPathStart load_path = LoadPathStart::scaled;
  // A cold load-controlled solve starts from the solution of the surface averaged over 2 x 2 blocks, solved
  // to 1e-4 (itself from a coarser one, down to 64 points a side), its pressure injected (docs/solvers.md).
  bool coarse_start = false;
  // Called before every iteration (none: nothing is called). It may throw to abandon the solve (a user's
  // Ctrl-C in the Python module): the exception leaves solve() or solve_for_separation(), and the solver
  // forgets its warm start, so the next solve starts afresh.
  std::function<void()> between_iterations = nullptr;
};

// The smallest tolerance single precision accepts: ten times float's epsilon (1.2e-7), with room for the
// round-off of the sums of an iteration.
inline constexpr Real kSinglePrecisionTolerance = 1e-6;

// The complementarity residual a converged solve may keep: `residual` (the largest |gap| on the contact set
// over the height range) at most kResidualPerTolerance x the tolerance. The pressure-change criteria can be
// met far from the solution (one iteration from a bad start, a tolerance of 0.5, heights or moduli at the
// ends of the double range): then the gap on the contact set is a sizeable part of the height range, and the
// solve is marked converged = false. Measured on surface A and an H = 0.8 surface at 256^2, periodic and not,
// every solver, tolerances 1e-12 to 1e-2, loads 1e-4 to 0.5 of E*: properly converged solves keep at most
// 23 x the tolerance (most under 10 x); plain Polonsky-Keer at a tolerance of 1e-2, non-periodic, stopped
// with a residual of 1.1, the whole height range. 100 leaves room above what converged solves showed.
inline constexpr Real kResidualPerTolerance = 100;
inline Real residual_bound(Real tolerance) {
  return kResidualPerTolerance * tolerance;
}

struct ContactSolution {
  HeightMap pressure;        // [Pa]
  HeightMap gap;             // [m], 0 on the contact set (plastic points included)
  Real mean_pressure = 0;    // P/A0 [Pa]: prescribed (solve), or the result (solve_for_separation)
  Real separation = 0;       // d: the flat's height above the mean plane of the heights [m] (found or given)
  Index contact_points = 0;  // points with p > 0 (with a hardness, the plastic ones too)
  Index iterations = 0;      // with a hardness: of every solve the search made, the elastic one included
  Index coarse_iterations = 0;  // of the coarse solves of a coarse start (each costs 1/4 of a finer one)
  Real change = 0;              // the last relative change of the pressure
  Real residual = 0;            // max |gap| on the (elastic) contact set / (max h - min h)
  bool converged = false;
  double seconds = 0;
  Index plastic_points = 0;  // points at p = H (with a hardness; 0 without), counted in contact_points too
};

class PolonskyKeer {
 public:
  // The surface's own periodicity chooses the operator (make_half_space); modulus is E* [Pa].
  PolonskyKeer(const Surface& surface, Real modulus, PolonskyKeerOptions options = {}, int threads = 1);
  ~PolonskyKeer();

  // Solves for the mean pressure P/A0 [Pa] (>= 0; 0 gives no contact), starting from the previous solution
  // when there is one (load stepping: solve increasing loads in order).
  const ContactSolution& solve(Real mean_pressure);

  // Solves with the flat at height `separation` [m] above the mean plane of the heights (the d of
  // ContactSolution::separation; see above), the load unknown: solution().mean_pressure is the resulting
  // P/A0. Warm-started like solve(). A flat at or above the highest point touches nothing (zero pressure).
  const ContactSolution& solve_for_separation(Real separation);

  const ContactSolution& solution() const { return solution_; }
  const Surface& surface() const { return surface_; }

 private:
  Surface surface_;
  PolonskyKeerOptions options_;
  Real engine_modulus_;
  int threads_;
  ContactSolution solution_;
  // The iteration, in the chosen scalar: the registry's solver (bem/solver_registry.hpp).
  std::unique_ptr<ContactSolver> engine_;
};

}  // namespace contactbench
