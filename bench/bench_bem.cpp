// The boundary-element solver on the paper's surface A (Table 1, 256 x 256 realisation) refined to n points
// a side by Fourier interpolation. Names: bem/<periodic|nonperiodic>/n:<n>/<solve|curve|cold_curve>, and the
// physical reference bem/fft_pair/n:<N> (one r2c + c2r pair of the padded size N the operator transforms: n
// periodic, 2n non-periodic). `curve` solves 10 loads in increasing order, each warm-started from the last;
// `cold_curve` solves the same 10 loads each from a cold start (a new solver), so that their `iterations`
// (the totals) say what warm starts save. Counters: iterations, ms_per_iteration, fft_pairs_per_iteration
// (one iteration's time over the time of one FFT pair of the same size, RealFft2d's default FFTW_ESTIMATE
// plans, measured in this binary just before) and fft_pairs_measured_per_iteration (the same over a pair of
// FFTW_MEASURE plans, the fastest FFTW offers: the stricter reference, since the solver's own transforms are
// measured plans too). All on kThreads threads.
#include <benchmark/benchmark.h>

#include <chrono>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "bench_surfaces.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/generation.hpp"

namespace contactbench::bench {
namespace {

const Index kSizes[] = {256, 1024, 2048};
constexpr Real kModulus = 100e9 / (1 - 0.3 * 0.3);
constexpr Real kLoad = 0.01;  // P/(E* A0), for a single solve

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

// Median-free but stable: the best of a few FFT pairs of the padded size, in ms.
double fft_pair_ms(Index size, FftRigor rigor = FftRigor::estimate) {
  static std::map<std::pair<Index, FftRigor>, double> cache;
  auto& slot = cache[{size, rigor}];
  if (slot == 0) {
    RealFft2d fft(size, size, kThreads, rigor);
    fft.real().setRandom();
    double best = 1e300;
    for (int repeat = 0; repeat < 5; ++repeat) {
      const auto start = std::chrono::steady_clock::now();
      fft.forward();
      fft.backward();
      best = std::min(
          best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    slot = best;
  }
  return slot;
}

void fft_pair(benchmark::State& state, Index size) {
  RealFft2d fft(size, size, kThreads);
  fft.real().setRandom();
  for (auto _ : state) {
    fft.forward();
    fft.backward();
    benchmark::DoNotOptimize(fft.real().data());
  }
}

enum class Run { solve, curve, cold_curve };

void solve(benchmark::State& state, Index n, bool periodic, Run run) {
  const Surface surface = refined_surface_a(n).with_periodic(periodic);
  const Index padded = periodic ? n : 2 * n;
  const double pair_ms = fft_pair_ms(padded), measured_pair_ms = fft_pair_ms(padded, FftRigor::measure);
  // Plain Polonsky-Keer, the record of results/bench/bem.md; the solvers are compared in bench_bem_solvers.
  const BemSolverOptions options{
      .tolerance = 1e-8, .max_iterations = 20000, .solver = SolverKind::polonsky_keer};
  Index iterations = 0;
  double seconds = 0;
  for (auto _ : state) {
    iterations = 0;
    seconds = 0;
    if (run == Run::solve) {
      BemSolver solver(surface, kModulus, options, kThreads);
      const ContactSolution& s = solver.solve(kModulus * kLoad);
      iterations = s.iterations;
      seconds = s.seconds;
    } else {
      // 10 loads from 0.001 to 0.01: warm, each from the last solution; cold, each by a new solver.
      BemSolver warm(surface, kModulus, options, kThreads);
      for (int k = 1; k <= 10; ++k) {
        std::unique_ptr<BemSolver> cold;
        if (run == Run::cold_curve) cold = std::make_unique<BemSolver>(surface, kModulus, options, kThreads);
        const ContactSolution& s = (cold ? *cold : warm).solve(kModulus * 0.001 * k);
        iterations += s.iterations;
        seconds += s.seconds;
      }
    }
  }
  const double ms_per_iteration = 1e3 * seconds / static_cast<double>(std::max<Index>(iterations, 1));
  state.counters["iterations"] = static_cast<double>(iterations);
  state.counters["ms_per_iteration"] = ms_per_iteration;
  state.counters["fft_pairs_per_iteration"] = ms_per_iteration / pair_ms;
  state.counters["fft_pairs_measured_per_iteration"] = ms_per_iteration / measured_pair_ms;
}

// cold_curve (10 solves from scratch) only up to 1024 points a side, and one repetition at 2048: a curve
// there takes minutes on two cores, and the command line's repetitions would multiply that.
constexpr Index kLargestColdCurve = 1024, kLargestRepeated = 1024;

void register_all() {
  std::set<Index> pairs;
  for (const Index n : kSizes)
    for (const bool periodic : {true, false})
      pairs.insert(periodic ? n : 2 * n);
  for (const Index padded : pairs)
    benchmark::RegisterBenchmark(("bem/fft_pair/n:" + std::to_string(padded)).c_str(), fft_pair, padded)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  for (const Index n : kSizes) {
    for (const bool periodic : {true, false}) {
      for (const auto& [run, label] : {std::pair{Run::solve, "solve"}, std::pair{Run::curve, "curve"},
                                       std::pair{Run::cold_curve, "cold_curve"}}) {
        if (run == Run::cold_curve && n > kLargestColdCurve) continue;
        const std::string name = std::string("bem/") + (periodic ? "periodic" : "nonperiodic") +
                                 "/n:" + std::to_string(n) + "/" + label;
        auto* benchmark = benchmark::RegisterBenchmark(name.c_str(), solve, n, periodic, run)
                              ->Unit(benchmark::kMillisecond)
                              ->UseRealTime()
                              ->Iterations(1);  // seconds to minutes a run at the larger sizes
        if (n > kLargestRepeated) benchmark->Repetitions(1);
      }
    }
  }
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  contactbench::bench::register_all();
  return contactbench::bench::run_benchmarks(argc, argv);
}
