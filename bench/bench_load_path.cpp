// How each BEM solver starts a load after the previous one, measured (docs/solvers.md "Starts: load
// stepping"): a 10-load curve solved with each start in the same run, against the same 10 loads solved
// cold. Names:
//   load_path/<solver>/<periodic|nonperiodic>/n:<n>/<surface>
// Loads: contact 1 % to 30 %, log-spaced (10 loads, nominal: P/(E* A0) = (pct/100) gbar/2, Persson's
// small-contact law with kappa = 2 and gbar the surface's rms gradient, as bench/bench_bem_solvers.cpp), in
// increasing order, tolerance 1e-8 (the paper scenes'). Surfaces: surface_a, the paper's surface A
// Fourier-refined to n x n; h08, a self-affine H = 0.8 surface rough down to each grid's pixel (both as in
// bench/bench_bem_solvers.cpp).
// Starts (LoadPathStart, bem/solver_registry.hpp): cold (each load as if alone: the solver's own cold
// start), scaled, extrapolated; and `solver`, the start the solver declares (SolverEntry::load_path), the
// one a scene gets (its counters copied from that start's). Every start's curve runs once per repetition, in
// that order, on one solver object (the FFT plans made before any is timed). Counters per start S:
// S_iterations (the curve's total, iterations as each solver counts them: active_set's coarse levels at a
// quarter), S_seconds (the solves' own time), S_ratio (its iterations over cold's), S_area_difference (the
// largest over the loads of |N - N_cold| / N_cold, N the contact nodes: the start must give the cold solves'
// answer to the tolerance). Iteration counts do not depend on the machine's load; times do (run with
// OMP_WAIT_POLICY=PASSIVE on a shared machine).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "bench_surfaces.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/bem/solvers/load_stepping.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench::bench {
namespace {

constexpr Real kModulus = 100e9 / (1 - 0.3 * 0.3);
constexpr Real kTolerance = 1e-8;
constexpr int kLoads = 10;
constexpr double kLowestContactPct = 1, kHighestContactPct = 30;

enum class SurfaceKind { surface_a, h08 };
const char* surface_label(SurfaceKind kind) {
  return kind == SurfaceKind::surface_a ? "surface_a" : "h08";
}

const Surface& case_surface(SurfaceKind kind, Index n) {
  static std::map<std::pair<SurfaceKind, Index>, std::unique_ptr<Surface>> cache;
  auto& slot = cache[{kind, n}];
  if (!slot) {
    const Grid grid = paper::grid();
    if (kind == SurfaceKind::surface_a) {
      slot = std::make_unique<Surface>(
          synthesize(grid, generate_coefficients(grid, paper::surface_a(), 1), n, n, kThreads));
    } else {
      const Grid fine{.nx = n, .ny = n, .lx = grid.lx, .ly = grid.ly, .periodic = true};
      const SelfAffinePsd psd{.sigma = 0.5e-6,
                              .hurst = 0.8,
                              .qr = 4 * 2 * std::numbers::pi / grid.lx,
                              .qs = std::nullopt,
                              .anisotropy = 1};
      slot = std::make_unique<Surface>(generate_surface(fine, psd, 2, kThreads));
    }
  }
  return *slot;
}

// The curve's loads P/A0 [Pa]: contact 1 % ... 30 % (nominal), log-spaced.
std::vector<Real> curve_loads(const Surface& surface) {
  const Real gbar = spectral_moments(surface, kThreads).rms_gradient();
  std::vector<Real> loads;
  for (int k = 0; k < kLoads; ++k) {
    const double pct =
        kLowestContactPct * std::pow(kHighestContactPct / kLowestContactPct, k / double(kLoads - 1));
    loads.push_back(kModulus * (pct / 100.0) * gbar / 2);
  }
  return loads;
}

struct Curve {
  Index iterations = 0;
  double seconds = 0;
  std::vector<Index> contact_points;
  bool converged = true;
};

Curve solve_curve(BemSolver& solver, const std::vector<Real>& loads) {
  Curve curve;
  solver.solve(0);  // no previous load: every start's curve begins cold
  for (const Real load : loads) {
    const ContactSolution& s = solver.solve(load);
    curve.iterations += s.iterations;
    curve.seconds += s.seconds;
    curve.contact_points.push_back(s.contact_points);
    curve.converged = curve.converged && s.converged;
  }
  return curve;
}

void load_path(benchmark::State& state, SolverKind solver_kind, SurfaceKind kind, Index n, bool periodic) {
  const Surface surface = case_surface(kind, n).with_periodic(periodic);
  const std::vector<Real> loads = curve_loads(surface);
  // `solver` is one of these (SolverEntry::load_path): its counters are copied from it, not measured twice.
  std::vector<LoadPathStart> starts{LoadPathStart::cold, LoadPathStart::scaled, LoadPathStart::extrapolated};
  std::vector<std::unique_ptr<BemSolver>> solvers;
  for (const LoadPathStart start : starts) {
    solvers.push_back(std::make_unique<BemSolver>(
        surface, kModulus,
        BemSolverOptions{
            .tolerance = kTolerance, .max_iterations = 100000, .solver = solver_kind, .load_path = start},
        kThreads));
    solvers.back()->solve(loads.front());  // the plans made, and any first-solve cost paid, untimed
  }
  std::vector<Curve> curves(starts.size());
  for (auto _ : state) {
    double seconds = 0;
    for (std::size_t i = 0; i < starts.size(); ++i) {
      curves[i] = solve_curve(*solvers[i], loads);
      if (!curves[i].converged) state.SkipWithError("a load did not converge");
      seconds += curves[i].seconds;
    }
    state.SetIterationTime(seconds);
  }
  const Curve& cold = curves.front();
  for (std::size_t i = 0; i < starts.size(); ++i) {
    const std::string label(load_path_start_name(starts[i]));
    double area_difference = 0;
    for (std::size_t k = 0; k < loads.size(); ++k)
      area_difference =
          std::max(area_difference,
                   std::abs(static_cast<double>(curves[i].contact_points[k] - cold.contact_points[k])) /
                       static_cast<double>(std::max<Index>(cold.contact_points[k], 1)));
    state.counters[label + "_iterations"] = static_cast<double>(curves[i].iterations);
    state.counters[label + "_seconds"] = curves[i].seconds;
    state.counters[label + "_ratio"] =
        static_cast<double>(curves[i].iterations) / static_cast<double>(cold.iterations);
    state.counters[label + "_time_ratio"] = curves[i].seconds / cold.seconds;
    state.counters[label + "_area_difference"] = area_difference;
  }
  // The start the solver declares: its counters again as solver_*, and its index in LoadPathStart's order
  // (scaled 0, extrapolated 1, cold 2).
  BemSolverOptions options{.solver = solver_kind};
  const LoadPathStart declared = load_path_start(options, surface.grid());
  for (const char* counter : {"_iterations", "_seconds", "_ratio", "_time_ratio", "_area_difference"})
    state.counters[std::string("solver") + counter] =
        state.counters[std::string(load_path_start_name(declared)) + counter];
  state.counters["declared"] = static_cast<double>(declared);
  state.counters["area_fraction"] =
      static_cast<double>(cold.contact_points.back()) / static_cast<double>(surface.grid().points());
}

void register_all() {
  for (const Index n : {256, 512, 1024})
    for (const bool periodic : {true, false})
      for (const SurfaceKind kind : {SurfaceKind::surface_a, SurfaceKind::h08})
        for (const std::string& name : solver_names()) {
          const std::string label = "load_path/" + name + "/" + (periodic ? "periodic" : "nonperiodic") +
                                    "/n:" + std::to_string(n) + "/" + surface_label(kind);
          benchmark::RegisterBenchmark(label.c_str(), load_path, solver_kind(name), kind, n, periodic)
              ->Unit(benchmark::kMillisecond)
              ->UseManualTime()
              ->Iterations(1);
        }
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  contactbench::bench::register_all();
  return contactbench::bench::run_benchmarks(argc, argv);
}
