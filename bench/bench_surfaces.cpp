#include "bench_surfaces.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <vector>

#include "contactbench/core/generation.hpp"

namespace contactbench::bench {

const Surface& rough_surface(Index n) {
  static std::map<Index, std::unique_ptr<Surface>> cache;
  auto& slot = cache[n];
  if (!slot) {
    const Grid grid{.nx = n, .ny = n, .lx = 200e-6, .ly = 200e-6, .periodic = true};
    slot = std::make_unique<Surface>(generate_surface(grid, paper::surface_a(), 1, kThreads));
  }
  return *slot;
}

const BinaryMap& contact_map(Index n, double coverage) {
  static std::map<std::pair<Index, double>, std::unique_ptr<BinaryMap>> cache;
  auto& slot = cache[{n, coverage}];
  if (!slot) {
    const HeightMap& h = rough_surface(n).heights();
    std::vector<Real> sorted(h.data(), h.data() + h.size());
    const auto above = static_cast<std::ptrdiff_t>(coverage * static_cast<double>(sorted.size()));
    // The level with `above` points strictly higher: the (size - above)-th smallest height.
    std::nth_element(sorted.begin(), sorted.end() - above - 1, sorted.end());
    slot = std::make_unique<BinaryMap>(threshold_above(h, *(sorted.end() - above - 1)));
  }
  return *slot;
}

void memory_pass(benchmark::State& state, Index n) {
  const HeightMap& heights = rough_surface(n).heights();
  LabelMap out(n, n);
  for (auto _ : state) {
    const Real* h = heights.data();
    std::int32_t* o = out.data();
#pragma omp parallel for num_threads(kThreads) schedule(static)
    for (Index i = 0; i < n * n; ++i)
      o[i] = h[i] > 0;
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n * n);
}

int run_benchmarks(int argc, char** argv, const std::vector<std::pair<std::string, std::string>>& context) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::AddCustomContext("threads", std::to_string(kThreads));
  for (const auto& [key, value] : context)
    benchmark::AddCustomContext(key, value);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace contactbench::bench
