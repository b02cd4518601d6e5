// The harmonic fill of invalid points (core/formats/harmonic_fill.cpp) on the shapes of holes measured files
// have, against one memory pass over the same grid in the same run (bench_surfaces.hpp):
//   fill/harmonic/<holes>/n:<n>   holes: random_half (each point invalid with probability 1/2),
//                                 half_plane (the left half), squares_64 (a checkerboard of 64-pixel
//                                 squares), sparse_valid (97 % invalid, isolated valid points)
//   fill/memory_pass/n:<n>        the floor
// The fill runs on one thread (its Gauss–Seidel sweeps are sequential); docs/formats.md quotes the medians.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "bench_surfaces.hpp"
#include "contactbench/core/formats/harmonic_fill.hpp"

namespace contactbench::bench {
namespace {

enum class Holes { random_half, half_plane, squares_64, sparse_valid };

std::vector<Real> holed_heights(Index n, Holes holes) {
  const HeightMap& heights = rough_surface(n).heights();
  std::vector<Real> values(heights.data(), heights.data() + heights.size());
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform;
  for (Index y = 0; y < n; ++y)
    for (Index x = 0; x < n; ++x) {
      bool invalid = false;
      switch (holes) {
        case Holes::random_half:
          invalid = uniform(random) < 0.5;
          break;
        case Holes::half_plane:
          invalid = x < n / 2;
          break;
        case Holes::squares_64:
          invalid = (x / 64 + y / 64) % 2 == 0;
          break;
        case Holes::sparse_valid:
          invalid = uniform(random) < 0.97;
          break;
      }
      if (invalid) values[static_cast<std::size_t>(y * n + x)] = std::numeric_limits<Real>::quiet_NaN();
    }
  return values;
}

void harmonic_fill(benchmark::State& state, Index n, Holes holes) {
  const std::vector<Real> holed = holed_heights(n, holes);
  HarmonicFillReport report;
  for (auto _ : state) {
    state.PauseTiming();
    std::vector<Real> values = holed;
    state.ResumeTiming();
    report = fill_harmonic(values, n, n);
    benchmark::DoNotOptimize(values.data());
  }
  state.counters["unknowns"] = static_cast<double>(report.unknowns);
  state.counters["iterations"] = static_cast<double>(report.iterations);
  state.counters["levels"] = static_cast<double>(report.levels);
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  using namespace contactbench;
  using namespace contactbench::bench;
  const std::pair<const char*, Holes> shapes[] = {{"random_half", Holes::random_half},
                                                  {"half_plane", Holes::half_plane},
                                                  {"squares_64", Holes::squares_64},
                                                  {"sparse_valid", Holes::sparse_valid}};
  for (const Index n : {512, 1024, 2048}) {
    register_timed("fill/memory_pass/n:" + std::to_string(n), memory_pass, n);
    for (const auto& [name, holes] : shapes)
      register_timed("fill/harmonic/" + std::string(name) + "/n:" + std::to_string(n), harmonic_fill, n,
                     holes);
  }
  return run_benchmarks(argc, argv);
}
