// Every key of a [methods.<label>] table with method = "bem", declared once (app/settings.hpp): the scene
// reader and writer, `contactbench bem`'s flags, the Python BemSolver's keywords, the MPI packing and the key
// table of scenes/README.md all come from bem_settings(). The solver's own options are BemSolver's
// (bem/bem_solver.hpp), reached through the rows, not copied. Adding a BEM option: a field of the solver's
// options (or of BemSettings for one of the method), one row below, and its line in scenes/README.md.
#pragma once

#include <optional>
#include <string>

#include "contactbench/app/settings.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/bem/bem_solver.hpp"

namespace contactbench {

// With extrapolate = true, the reference's error bar (bem/grid_convergence.hpp): Roache's GCI on two or three
// grids, or the bar calibrated on three (docs/theory.md section 9.2).
enum class ErrorEstimate { gci2, gci3, calibrated3 };

// The estimates that need a third grid.
inline bool uses_third_grid(ErrorEstimate estimate) {
  return estimate != ErrorEstimate::gci2;
}

struct BemSettings {
  Index refine = 0;              // points a side after Fourier refinement; 0: the scene's surface as it is
  std::optional<bool> periodic;  // none: the surface's own periodicity
  BemSolverOptions solver = {};  // tolerance, iteration cap, precision, iteration (hardness: the interface's)
  std::string fields;            // prefix of per-load pressure and gap files; empty: none written
  std::string residual_topography;  // the surface after the load path, written there; empty: not written
  bool extrapolate = false;         // solve again on twice the points a side (docs/theory.md section 9)
  ErrorEstimate error_estimate = ErrorEstimate::gci3;  // the error bar's grids (with extrapolate)
  int connectivity = 4;                                // for counting contact spots
  bool node_area = false;  // area = "nodes": compared by the node count (a node-based FE model's area)
  bool allow_unconverged = false;  // unconverged loads marked, the run exits 0
  // boundary = "mirrored": a non-periodic surface solved as its periodic even extension to twice the points
  // a side, judged on the original patch (app/mirrored_boundary.hpp); false: "as_is", the finite patch;
  // unset: resolve_boundary's default. A stage's settings hold the resolved value.
  std::optional<bool> mirrored;
  // With interface.adhesion: how the adhesive problem is solved (bem/adhesive_solver.hpp)
  AdhesiveMethod adhesive_method = AdhesiveMethod::fixed_point;
};

const SettingTable<BemSettings>& bem_settings();

// error_estimate = "calibrated3" or "gci3": the third grid is half the solved grid when the scene's surface
// has at most that many points a side (the same band-limited surface, and a quarter of the solve's cost
// more), else twice the finer grid (16 times the single solve more). `solved_*` are the points a side of the
// first solve.
inline bool third_grid_is_coarser(Index solved_nx, Index solved_ny, Index surface_nx, Index surface_ny) {
  return solved_nx % 2 == 0 && solved_ny % 2 == 0 && solved_nx / 2 >= surface_nx &&
         solved_ny / 2 >= surface_ny;
}

// The boundary a BEM stage solves (docs/solvers.md "Mirrored boundary"): the declared one when `boundary`
// is given; unset, "mirrored" on a non-periodic problem where it is available (results/studies/edges: the
// treatment closest to the periodic truth), else "as_is" with the reason, which the run's parameters print,
// so that an unset boundary never changes silently. A declared "mirrored" where it is not available is the
// preflight's refusal, not a fallback.
struct ResolvedBoundary {
  bool mirrored = false;
  std::string as_is_because;  // unset boundary, non-periodic problem, solved as is: why (else empty)
};
ResolvedBoundary resolve_boundary(const BemSettings& settings, bool periodic, bool adhesion);

// The tolerances a scene, the command line or Python may ask for: in double precision [1e-13, 1e-2] (above,
// a solve stops far from the solution; below, the relative change of a sum over millions of nodes is
// round-off); in single precision from kSinglePrecisionTolerance, also its default.
inline constexpr Real kSmallestTolerance = 1e-13;
inline constexpr Real kLargestTolerance = 1e-2;
inline constexpr Real kDefaultTolerance = 1e-8;

// The rules between keys, after every key is read: the tolerance's default and least value in single
// precision, area = "nodes" with extrapolate. `given` lists the keys set explicitly; each problem goes to
// `problem(key, reason, accepted)`.
void finish_bem_settings(
    BemSettings& settings, const std::vector<std::string>& given,
    const std::function<void(const std::string&, const std::string&, const std::string&)>& problem);

}  // namespace contactbench
