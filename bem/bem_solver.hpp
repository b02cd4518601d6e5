// The boundary-element ground truth: frictionless normal contact of a rough rigid surface and an elastic
// half-space, solved for a prescribed mean pressure (solve) or a prescribed height of the flat
// (solve_for_separation), elastic or capped at a hardness, periodic or not, in double or single precision
// (docs/solvers.md "The problem every solver solves"; the physics in docs/theory.md section 6). Three
// iterations solve it (options.solver, bem/solver_registry.hpp; docs/solvers.md "How to choose"), each a
// class behind one interface (bem/solvers/contact_solver.hpp); this class is the one callers use.
//
// The gap is g = d - h + u(p) >= 0, u = G p (bem/half_space.hpp), d the flat's height above the mean plane of
// the heights (ContactSolution::separation): under separation control in the periodic case d is the mean gap
// and must be > 0, in the non-periodic case the rigid-body approach is max h - d (docs/solvers.md
// "Separation control"). A solve is converged only when its stopping criterion is met AND the
// complementarity residual is at most residual_bound(tolerance) (below; docs/solvers.md "Stopping criteria
// and what the tolerance buys"); a solve that reaches the iteration cap is marked converged = false and says
// so through the options' warning sink. A hardness makes nodes at p = H plastic (docs/solvers.md "Hardness").
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

struct FlatHeightMemory;

struct BemSolverOptions {
  Real tolerance = 1e-10;  // of the stopping criterion (docs/solvers.md "Stopping criteria ...")
  Index max_iterations = 20000;
  // The indentation hardness H [Pa] of a perfectly plastic cap p <= H (docs/solvers.md "Hardness"); none:
  // elastic. A mean pressure P/A0 >= H is refused: the whole surface would be plastic (full plastic contact,
  // p = H everywhere, the flat's height undetermined).
  std::optional<Real> hardness = std::nullopt;
  // With a hardness: keep the plastic deformation from one load to the next (docs/solvers.md "Hardness",
  // "Unloading and reloading"). After each load-controlled solve the heights of the plastic nodes are lowered
  // by their overlap with the flat (h <- h + g where p = H and the raw gap g < 0), so that the deformed
  // surface meets the flat with gap 0 there and the same pressure; the next load, higher or lower, is solved
  // on the deformed surface (BemSolver::surface()). Off: every load is solved on the surface as given.
  bool keep_plastic_deformation = false;
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
  // Where solve() starts a load after a previous one (load stepping, loads in increasing order): as the
  // solver declares (SolverEntry::load_path, chosen by measurement: docs/solvers.md "Starts"), or forced
  // to one of the starts (LoadPathStart, bem/solver_registry.hpp).
  LoadPathStart load_path = LoadPathStart::solver;
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

// The magnitudes single precision accepts (float holds 1.2e-38 to 3.4e38; sums of squares and products of
// the scales below need room): outside, heights of 1e-99 m became 0 in float and the solve reported
// "converged" with no contact (tests/test_hard_cases.cpp).
inline constexpr Real kSinglePrecisionSmallest = 1e-30;
inline constexpr Real kSinglePrecisionLargest = 1e30;
// Throws Error naming the quantity unless the heights' range, the pixel, the pressure scale E* h / dx and the
// compliance dx / E* of a single-precision solve of `surface` (E* = modulus) lie in that range.
void check_single_precision_range(const Surface& surface, Real modulus);

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
  // With a hardness: the overlap -g >= 0 [m] of each plastic node with the flat (its raw gap, before the
  // gap above is set to 0 there), 0 elsewhere: the depth the surface flowed at this state. Empty without a
  // hardness.
  HeightMap plastic_overlap;
};

class BemSolver {
 public:
  // The surface's own periodicity chooses the operator (make_half_space); modulus is E* [Pa].
  BemSolver(const Surface& surface, Real modulus, BemSolverOptions options = {}, int threads = 1);
  ~BemSolver();

  // Solves for the mean pressure P/A0 [Pa] (>= 0; 0 gives no contact), starting from the previous solution
  // when there is one (load stepping: solve increasing loads in order).
  const ContactSolution& solve(Real mean_pressure);

  // Solves with the flat at height `separation` [m] above the mean plane of the heights (the d of
  // ContactSolution::separation; docs/solvers.md "Separation control"), the load unknown:
  // solution().mean_pressure is the resulting P/A0. Warm-started like solve(). A flat at or above the highest
  // point touches nothing (zero pressure).
  const ContactSolution& solve_for_separation(Real separation);

  const ContactSolution& solution() const { return solution_; }
  // The surface the next solve presses: the given one less its mean height, and, with
  // keep_plastic_deformation, lowered where earlier loads made it flow (the residual topography, heights
  // above the given surface's mean plane).
  const Surface& surface() const { return surface_; }

 private:
  Surface surface_;
  BemSolverOptions options_;
  Real engine_modulus_;
  int threads_;
  ContactSolution solution_;
  // The iteration, in the chosen scalar: the registry's solver (bem/solver_registry.hpp).
  std::unique_ptr<ContactSolver> engine_;
  // With a hardness, for the solvers that meet it by a search on the flat's height: what the last load's
  // search left (bem/solvers/hardness_search.hpp); empty when the engine's state is not that search's.
  std::unique_ptr<FlatHeightMemory> flat_height_;
  // keep_plastic_deformation: lowers the plastic nodes of solution_ by their overlap (in surface_ and the
  // engine's heights).
  void keep_plastic_deformation();
};

}  // namespace contactbench
