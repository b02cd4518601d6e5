// The solver "active_set" (bem/solver_registry.hpp; docs/solvers.md): a primal-dual active-set
// (semismooth Newton) method for the contact problem of bem/polonsky_keer.hpp: under load control or
// separation control, elastic or with pressures capped at a hardness H (perfectly plastic).
//
// Guess the contact set A; solve the LINEAR problem on it (gap = 0 on A, p = 0 elsewhere, sum p = the load)
// by a conjugate gradient preconditioned by the Fourier filter (E*/2)|q| (bem/fourier_preconditioner.hpp; in
// single precision whatever the solver's, as it only shapes the search direction) applied to the residual
// extended off A by its local averages (the extended filter, bem/box_sum.hpp), the result gathered back onto
// A by the transpose and its mean there removed; then update the set, A <- {i in A:
// p_i > 0} u {i not in A: g_i < 0}, and repeat. The outer steps settle the set; the inner CG sees a fixed
// set, so it is a plain preconditioned CG whose convergence is not disturbed by nodes entering and leaving.
// Inner solves stop at a loose relative residual (kInnerReduction), or once the gap on the set is within the
// convergence threshold below, while the set still changes, which is what makes the outer steps cheap; once
// the set has not changed, the last inner solve runs to the tolerance.
//
// A cold solve starts from a nested coarse solution: the surface averaged over 2 x 2 blocks solved the same
// way (itself from a coarser one, down to kCoarsest points a side), its pressure interpolated bilinearly to
// the fine grid, and the starting set {p - k g > 0} with k the stiffness of one pixel (1/G(0)), under load
// control cut to the nodes of the largest p - k g, as many as the coarse solution touches: where active set
// methods get outer iteration counts that barely grow with the grid. A warm start (load stepping) starts
// from the previous pressure scaled to the load, on its contact set {p > 0}.
//
// Converged means: the set did not change in the last outer step (so p >= 0 on A and no node off A
// penetrates beyond round-off, or beyond the threshold below after 30 outer steps), AND the complementarity
// residual, the largest |g| on A, is at most the threshold tolerance x (max h - d) (the approach of the
// highest point: the scale of the gaps that matter, where the height range could be made of a pit nothing
// touches; never below the gap's round-off), AND the last CG step changed the pressure by at most the
// tolerance relative (PK's criterion, on a settled set; a final solve that starts with the gap within the
// threshold takes no step and so meets it). The test is thus on the residual itself, not only on a change
// that a stalled iteration could make small. Nodes enter when they penetrate beyond the gap's round-off, so
// that the area is not biased low by the nodes penetrating less than the threshold; after 30 outer steps only
// beyond the threshold (nodes at p = 0 and g = 0 within it could otherwise flip in and out for ever). The
// iteration count: the inner CG iterations (each one application of G and one of the filter: two FFT pairs,
// padded for non-periodic grids), plus one per outer step whose start needs a fresh displacement G p (more
// than 16 nodes left the set or became plastic; nodes that only entered, at p = 0, change nothing, and up to
// 16 changed pressures are added to G p as their columns of G, a pass over the grid per node, not a
// transform, so not counted: its time is in the solve's), plus the starting set's gap and the final gap (made
// again only after a clipping, or when the CG's steps could have moved u from G p by a thousandth of the
// threshold: single precision, or tolerances near round-off), plus the coarse levels' work: each level's
// iterations count a quarter of the next finer level's (a quarter of the points; the transforms' N log N cost
// a little less), summed over the levels and rounded once, to the nearest iteration (before, rounded up at
// each level: up to one iteration more per level).
//
// Separation control: the flat's height d is given, so the linear problem on A is gap = 0 there with no
// condition on the sum and no mean taken out of the residual, the filtered residual or G's response (the
// load is what comes out). A hardness adds a third set, the plastic nodes P where p = H (docs/theory.md):
// the linear problem is solved on the elastic set A with p = H held on P (its displacement is part of the
// gap; under load control the elastic nodes carry the load less H |P|), and the update also moves nodes
// of A whose pressure exceeds H into P, and nodes of P whose gap opens by more than the threshold back
// into A (from a cold start only once the elastic sets have settled: see active_set.cpp). Under load
// control, should the elastic set empty or the plastic nodes carry the whole load, the sets are made again as
// the bearing area's (the limit of a very soft contact). A capped solve under load control is thus one solve,
// where the other solvers search the flat's height with capped solves under separation control
// (polonsky_keer.cpp, solve_capped).
#pragma once

#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct ActiveSetOutcome {
  Index iterations = 0;  // inner CG iterations + outer steps (+ coarse levels, see above): `work` rounded
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
// levels from solve to solve.
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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contactbench
