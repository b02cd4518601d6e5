// What the contact stiffness K = -dP/dd of the BEM costs (bem/contact_stiffness.hpp; docs/solvers.md, "The
// stiffness solve"). The case of scenes/paper/surface_A_gap.toml: the paper's surface A (Table 1, the
// 256 x 256 realisation of seed 1) Fourier-refined to 512 x 512, periodic, E* = 100 GPa / (1 - 0.3^2), its
// 12 loads P/(E* A0) = 1e-4 ... 2e-2 (log-spaced), each solved once by active_set at 1e-8 (not timed). Names:
//   contact_stiffness/n:512/<path>:<tolerance>   the 12 stiffness solves, in load order
//   contact_stiffness/n:512/fft_pair              one application of the half-space operator (an FFT pair)
// <path>: before (the implementation before issue 36, copied below: plans per load, separate array passes),
// one_state (contact_stiffness per load: the fused iteration, plans per load) or stage (one
// ContactStiffnessSolver for the 12 loads, its plans made once, as app/serial_runner.cpp runs them).
// Counters: iterations (the sum over the loads), iterations_<k> per load, ms_per_iteration,
// fft_pairs_per_iteration (against the fft_pair benchmark of the same run, when it ran first), and k_error,
// the largest relative difference of K over the loads from the before:1e-10 solve (the first benchmark;
// computed untimed if filtered out).
#include <benchmark/benchmark.h>

#include <algorithm>
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
#include "contactbench/core/fft.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"

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

// The stiffness solve as it was before issue 36 (bem/contact_stiffness.cpp at commit 188885b), kept here as
// the "before" of the same run: a fresh operator and transform planned per call, each CG step as separate
// Eigen passes over full arrays, K = mean(x), to the relative residual `tolerance`.
ContactStiffness previous_contact_stiffness(const Grid& grid, Real modulus, const HeightMap& pressure,
                                            int threads, Real tolerance) {
  ContactStiffness result;
  const HeightMap mask = (pressure > 0).cast<Real>();
  const auto on_set = static_cast<Index>(mask.sum());
  const Index points = grid.points();
  std::unique_ptr<HalfSpace> operator_g = make_half_space(grid, modulus, threads);
  RealFft2d fft(grid.nx, grid.ny, threads);
  const HalfLattice lattice(grid);
  const auto qx = lattice.qx_row();
  const auto qy = lattice.qy_column();
  const Real smallest = std::min(grid.dqx(), grid.dqy());
  Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> inverse(grid.ny, fft.nx_half());
  for (Index row = 0; row < grid.ny; ++row)
    for (Index col = 0; col < fft.nx_half(); ++col)
      inverse(row, col) =
          modulus / 2 * std::max(std::hypot(qx(col), qy(row)), smallest) / static_cast<Real>(points);
  const auto precondition = [&](const HeightMap& residual, HeightMap& out) {
    fft.real() = residual * mask;
    fft.forward();
    fft.spectrum() *= inverse.cast<Complex>();
    fft.backward();
    out = fft.real() * mask;
  };
  HeightMap x = HeightMap::Zero(grid.ny, grid.nx);
  HeightMap r = mask;
  HeightMap z(grid.ny, grid.nx), a_d(grid.ny, grid.nx);
  precondition(r, z);
  HeightMap d = z;
  const Real b_norm = std::sqrt(static_cast<Real>(on_set));
  Real rz = (r * z).sum(), rr = (r * r).sum();
  for (Index it = 0; it < 5000; ++it) {
    if (std::sqrt(rr) <= tolerance * b_norm) {
      result.converged = true;
      break;
    }
    operator_g->apply(d, a_d);
    a_d *= mask;
    const Real step = rz / (d * a_d).sum();
    x += step * d;
    r -= step * a_d;
    rr = (r * r).sum();
    precondition(r, z);
    const Real rz_next = (r * z).sum();
    d = z + (rz_next / rz) * d;
    rz = rz_next;
    result.iterations = it + 1;
  }
  result.residual = std::sqrt(rr) / b_norm;
  result.stiffness = x.sum() / static_cast<Real>(points);
  return result;
}

double fft_pair_ms = 0;
std::vector<Real> reference_stiffness;

enum class Path { before, one_state, stage };

std::vector<ContactStiffness> solve_all(Path path, Real tolerance) {
  const States& states = scene_states();
  std::vector<ContactStiffness> out;
  if (path == Path::stage) {
    ContactStiffnessSolver solver(states.grid, kModulus, std::nullopt, kThreads, {.tolerance = tolerance});
    for (const HeightMap& p : states.pressures)
      out.push_back(solver.solve(p));
  } else if (path == Path::one_state) {
    for (const HeightMap& p : states.pressures)
      out.push_back(contact_stiffness(states.grid, kModulus, p, std::nullopt, kThreads, tolerance));
  } else {
    for (const HeightMap& p : states.pressures)
      out.push_back(previous_contact_stiffness(states.grid, kModulus, p, kThreads, tolerance));
  }
  return out;
}

void stiffness_solves(benchmark::State& state, Path path, Real tolerance) {
  const States& states = scene_states();  // (solved before the timing starts)
  (void)states;
  if (reference_stiffness.empty() && !(path == Path::before && tolerance == 1e-10))
    for (const ContactStiffness& k : solve_all(Path::before, 1e-10))
      reference_stiffness.push_back(k.stiffness);
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<ContactStiffness> solved = solve_all(path, tolerance);
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
  const std::pair<const char*, std::pair<Path, double>> cases[] = {
      {"before:1e-10", {Path::before, 1e-10}},
      {"before:1e-5", {Path::before, 1e-5}},
      {"one_state:1e-10", {Path::one_state, 1e-10}},
      {"stage:1e-10", {Path::stage, 1e-10}},
      {"stage:1e-5", {Path::stage, 1e-5}}};
  for (const auto& [label, setting] : cases)
    register_timed(std::string("contact_stiffness/n:512/") + label, stiffness_solves, setting.first,
                   setting.second)
        ->Iterations(1)
        ->Repetitions(3)
        ->ReportAggregatesOnly(true);
  return run_benchmarks(argc, argv,
                        {{"surface", "paper surface A seed 1, Fourier-refined to 512, 12 scene loads"}});
}
