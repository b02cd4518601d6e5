// What adhesion costs the boundary-element reference (docs/solvers.md "Adhesion"). Names:
//   bem_adhesion/<dugdale|exponential>/<periodic|nonperiodic>/n:<n>/tabor:<t>/method:<m>
// m: the AdhesiveSolverOptions::method, fixed_point, (Dugdale only) constrained_cg or (exponential,
// periodic only) projected_lbfgs.
// One case: the paper's surface A (Table 1, the 256 x 256 realisation of seed 1) Fourier-refined to n x n,
// soft (E* = 4 MPa) and clean (w = 50 mJ/m^2), the scenes/adhesion material; σ0 such that Maugis' parameter
// λ = 2σ0 (9R/(16π w E*²))^(1/3) of a summit of radius R = 1/h''_rms (the rms curvature of docs/theory.md
// 10.5) is t (the exponential law: the same work and peak stress, ρ = w/σ0). The load P/(E* A0) = 0.025 gbar
// (about 5 % contact without adhesion, gbar the rms gradient).
// Each repetition times, from a cold start: the adhesive solve at that load (AdhesiveBemSolver around
// active_set, the scene's default) and, in the same run, the non-adhesive active_set solve at the same mean
// pressure (BemSolver), both at the contact tolerance 1e-6. Counters: iterations and outer_iterations of the
// adhesive solve, cg_iterations (constrained_cg: the whole-surface CG's steps; projected_lbfgs: its
// quasi-Newton steps, its energy evaluations being `iterations`); residual (the force imbalance the adhesive
// solve stopped at, units of the law's peak stress: both methods stop at 100 x the tolerance);
// elastic_iterations,
// elastic_seconds; ratio (adhesive over non-adhesive time, the figure of issue 34: goal <= 5 at 1024^2);
// zone_pixels (the attractive zone's width at the contact edge), area_fraction and elastic_area_fraction;
// load_potential (U + (P/A0) d of the adhesive state, J/m^2);
// converged. Reported: the medians of 3 repetitions.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include "bench_surfaces.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench::bench {
namespace {

constexpr Real kModulus = 4e6, kWork = 0.05, kTolerance = 1e-6;

const Surface& refined_surface_a(Index n) {
  static std::map<Index, std::unique_ptr<Surface>> cache;
  auto& slot = cache[n];
  if (!slot) {
    const Grid grid = paper::grid();
    slot = std::make_unique<Surface>(
        synthesize(grid, generate_coefficients(grid, paper::surface_a(), 1), n, n, kThreads));
  }
  return *slot;
}

AdhesionLaw law_at_tabor(AdhesionModel model, const SpectralMoments& m, Real tabor) {
  const Real m4 = (m.m4x + m.m4y) / 2;  // the isotropic profile moment
  const Real radius = 1 / (std::sqrt(8 * m4 / 3) / 2);
  const Real stress = tabor / 2 / std::cbrt(9 * radius / (16 * M_PI * kWork * kModulus * kModulus));
  return model == AdhesionModel::dugdale ? AdhesionLaw::dugdale(kWork, stress)
                                         : AdhesionLaw::exponential(kWork, kWork / stress);
}

void adhesive_solve(benchmark::State& state, AdhesionModel model, bool periodic, Index n, Real tabor,
                    AdhesiveMethod method) {
  const Surface surface = refined_surface_a(n).with_periodic(periodic);
  const SpectralMoments moments = spectral_moments(surface, kThreads);
  const AdhesionLaw law = law_at_tabor(model, moments, tabor);
  const Real pressure = kModulus * 0.025 * moments.rms_gradient();
  const BemSolverOptions contact{.tolerance = kTolerance, .solver = SolverKind::active_set};
  for (auto _ : state) {
    state.PauseTiming();
    AdhesiveBemSolver adhesive(surface, kModulus, law, {.contact = contact, .method = method}, kThreads);
    BemSolver elastic(surface, kModulus, contact, kThreads);
    state.ResumeTiming();
    const auto start = std::chrono::steady_clock::now();
    const AdhesiveSolution& a = adhesive.solve(pressure);
    const double adhesive_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    const auto elastic_start = std::chrono::steady_clock::now();
    const ContactSolution& e = elastic.solve(pressure);
    const double elastic_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - elastic_start).count();
    const double points = static_cast<double>(surface.grid().nx * surface.grid().ny);
    state.counters["iterations"] = static_cast<double>(a.iterations);
    state.counters["outer_iterations"] = static_cast<double>(a.outer_iterations);
    state.counters["cg_iterations"] = static_cast<double>(a.cg_iterations);
    state.counters["seconds"] = adhesive_seconds;
    state.counters["elastic_iterations"] = static_cast<double>(e.iterations);
    state.counters["elastic_seconds"] = elastic_seconds;
    state.counters["ratio"] = adhesive_seconds / elastic_seconds;
    state.counters["zone_pixels"] = a.zone_pixels;
    state.counters["residual"] = a.attraction_change;
    // U + (P/A0) d [J/m^2]: the potential that load control makes stationary (dU/dd = -P/A0, docs/theory.md
    // 10.7), to compare the equilibria two methods end on at the same load (the lower is the more stable).
    state.counters["load_potential"] = adhesive.energy() + a.mean_pressure * a.separation;
    state.counters["area_fraction"] = static_cast<double>(a.contact_points) / points;
    state.counters["elastic_area_fraction"] = static_cast<double>(e.contact_points) / points;
    state.counters["converged"] = a.converged && e.converged ? 1 : 0;
    state.ResumeTiming();
  }
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  using namespace contactbench;
  using namespace contactbench::bench;
  for (const AdhesionModel model : {AdhesionModel::dugdale, AdhesionModel::exponential})
    for (const bool periodic : {true, false})
      for (const Index n : {256, 512, 1024, 2048})
        for (const Real tabor : {0.1, 1.0, 5.0})
          for (const AdhesiveMethod method : {AdhesiveMethod::fixed_point, AdhesiveMethod::constrained_cg,
                                              AdhesiveMethod::projected_lbfgs}) {
            if (!adhesive_method_refusal(method, model, periodic).reason.empty()) continue;
            char tabor_text[16];
            std::snprintf(tabor_text, sizeof tabor_text, "%g", tabor);
            const std::string name = "bem_adhesion/" + std::string(adhesion_model_name(model)) + "/" +
                                     (periodic ? "periodic" : "nonperiodic") + "/n:" + std::to_string(n) +
                                     "/tabor:" + tabor_text +
                                     "/method:" + std::string(adhesive_method_name(method));
            register_timed(name, adhesive_solve, model, periodic, n, tabor, method)
                ->Iterations(1)
                ->Repetitions(3)
                ->ReportAggregatesOnly(true);
          }
  return run_benchmarks(argc, argv, {{"surface", "paper surface A seed 1, Fourier-refined"}});
}
