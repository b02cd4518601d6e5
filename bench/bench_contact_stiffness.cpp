// What the contact stiffness K = -dP/dd of the BEM costs (bem/contact_stiffness.hpp; docs/solvers.md, "The
// stiffness solve"). The case of scenes/paper/surface_A_gap.toml: the paper's surface A (Table 1, the
// 256 x 256 realisation of seed 1) Fourier-refined to 512 x 512, periodic, E* = 100 GPa / (1 - 0.3^2), its
// 12 loads P/(E* A0) = 1e-4 ... 2e-2 (log-spaced), each solved once by active_set at 1e-8 (not timed). Names:
//   contact_stiffness/n:512/<path>:<tolerance>   the 12 stiffness solves, in load order
//   contact_stiffness/n:512/fft_pair              one application of the half-space operator (an FFT pair)
// <path>: cold (a fresh solver per load: the path before issue 36) or stage (one ContactStiffnessSolver, its
// plans made once, for the 12 loads, as app/serial_runner.cpp runs them). Counters: iterations (the
// sum over the loads), iterations_<k> per load, ms_per_iteration, fft_pairs_per_iteration (against the
// fft_pair benchmark of the same run, when it ran first), and k_error, the largest relative difference of K
// over the loads from the cold 1e-10 solve (the first benchmark; computed untimed if filtered out).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "bench_surfaces.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_stiffness.hpp"
#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/generation.hpp"

namespace contactbench::bench {
namespace {

constexpr Real kModulus = 100e9 / (1 - 0.3 * 0.3);
constexpr Index kSize = 512;

struct States {
  Grid grid;
  std::vector<HeightMap> pressures;
};

const States& scene_states() {
  static std::unique_ptr<States> states;
  if (!states) {
    const Grid grid = paper::grid();
    const Surface surface =
        synthesize(grid, generate_coefficients(grid, paper::surface_a(), 1), kSize, kSize, kThreads);
    BemSolver solver(surface, kModulus, {.tolerance = 1e-8}, kThreads);
    states = std::make_unique<States>(States{.grid = surface.grid(), .pressures = {}});
    for (int k = 0; k < 12; ++k) {
      const Real load = 1e-4 * std::pow(2e-2 / 1e-4, k / 11.0);
      states->pressures.push_back(solver.solve(load * kModulus).pressure);
    }
  }
  return *states;
}

double fft_pair_ms = 0;
std::vector<Real> reference_stiffness;

std::vector<ContactStiffness> solve_all(bool stage, Real tolerance) {
  const States& states = scene_states();
  std::vector<ContactStiffness> out;
  if (stage) {
    ContactStiffnessSolver solver(states.grid, kModulus, std::nullopt, kThreads, {.tolerance = tolerance});
    for (const HeightMap& p : states.pressures)
      out.push_back(solver.solve(p));
  } else {
    for (const HeightMap& p : states.pressures)
      out.push_back(contact_stiffness(states.grid, kModulus, p, std::nullopt, kThreads, tolerance));
  }
  return out;
}

void stiffness_solves(benchmark::State& state, bool stage, Real tolerance) {
  const States& states = scene_states();  // (solved before the timing starts)
  (void)states;
  if (reference_stiffness.empty() && !(!stage && tolerance == 1e-10))
    for (const ContactStiffness& k : solve_all(false, 1e-10))
      reference_stiffness.push_back(k.stiffness);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<ContactStiffness> solved = solve_all(stage, tolerance);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    state.PauseTiming();
    if (reference_stiffness.empty())
      for (const ContactStiffness& k : solved)
        reference_stiffness.push_back(k.stiffness);
    double iterations = 0, k_error = 0;
    bool converged = true;
    for (std::size_t k = 0; k < solved.size(); ++k) {
      iterations += static_cast<double>(solved[k].iterations);
      char name[32];
      std::snprintf(name, sizeof name, "iterations_%02zu", k + 1);
      state.counters[name] = static_cast<double>(solved[k].iterations);
      k_error = std::max(k_error, std::abs(solved[k].stiffness / reference_stiffness[k] - 1));
      converged = converged && solved[k].converged;
    }
    state.counters["iterations"] = iterations;
    state.counters["ms_per_iteration"] = ms / iterations;
    if (fft_pair_ms > 0) state.counters["fft_pairs_per_iteration"] = ms / iterations / fft_pair_ms;
    state.counters["k_error"] = k_error;
    state.counters["converged"] = converged ? 1 : 0;
    state.ResumeTiming();
  }
}

void fft_pair(benchmark::State& state) {
  const Grid grid = scene_states().grid;
  auto operator_g = make_half_space(grid, kModulus, kThreads);
  const HeightMap in = scene_states().pressures.back();
  HeightMap out(grid.ny, grid.nx);
  double total = 0, count = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    operator_g->apply(in, out);
    total += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    ++count;
    benchmark::DoNotOptimize(out.data());
  }
  fft_pair_ms = total / count;
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  using namespace contactbench::bench;
  register_timed("contact_stiffness/n:512/fft_pair", fft_pair)->Repetitions(3)->ReportAggregatesOnly(true);
  const std::pair<const char*, std::pair<bool, double>> cases[] = {{"cold:1e-10", {false, 1e-10}},
                                                                   {"cold:1e-5", {false, 1e-5}},
                                                                   {"stage:1e-10", {true, 1e-10}},
                                                                   {"stage:1e-5", {true, 1e-5}}};
  for (const auto& [label, setting] : cases)
    register_timed(std::string("contact_stiffness/n:512/") + label, stiffness_solves, setting.first,
                   setting.second)
        ->Iterations(1)
        ->Repetitions(3)
        ->ReportAggregatesOnly(true);
  return run_benchmarks(argc, argv,
                        {{"surface", "paper surface A seed 1, Fourier-refined to 512, 12 scene loads"}});
}
