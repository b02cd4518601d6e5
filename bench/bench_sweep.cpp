// The geometric sweep on the project's rough surfaces. Names: sweep/<mode>/n:<n>/conn:<c>, with mode
//   levels500  the paper's 500 levels (steps of 0.002 h_max down to the mean plane), one union-find pass
//   exact      every distinct height, one union-find pass
//   per_level  the same 500 levels by thresholding and labelling each with the project's labeller
//   memory_pass  one pass that reads the heights and writes int32 (the floor, as in bench_labelling)
// All on bench::kThreads threads; surfaces are not periodic here (as for measured data).
#include <benchmark/benchmark.h>

#include <string>

#include "bench_surfaces.hpp"
#include "contactbench/core/labelling.hpp"
#include "contactbench/core/sweep.hpp"

namespace contactbench::bench {
namespace {

const Index kSizes[] = {256, 1024, 4096};
const Connectivity kConnectivities[] = {Connectivity::four, Connectivity::eight};

void run_sweep(benchmark::State& state, Index n, Connectivity c, SweepLevels levels) {
  const Surface& surface = rough_surface(n);
  const Topology topology{c, false, false};
  Index level_count = 0;
  for (auto _ : state) {
    const SweepCurve curve = sweep(surface, levels, topology, kThreads);
    level_count = static_cast<Index>(curve.z.size());
    benchmark::DoNotOptimize(curve.spots.data());
  }
  state.SetItemsProcessed(state.iterations() * n * n);
  state.counters["levels"] = static_cast<double>(level_count);
}

// What the sweep replaces: label each of the paper's 500 levels separately.
void per_level(benchmark::State& state, Index n, Connectivity c) {
  const Surface& surface = rough_surface(n);
  const Real top = surface.heights().maxCoeff();
  Labeller labeller(Topology{c, false, false}, kThreads);
  BinaryMap map(n, n);
  for (auto _ : state) {
    Index spots = 0;
    for (int k = 0; k <= 500; ++k) {
      map = threshold_above(surface.heights(), top - k * (top / 500));
      spots += labeller.label(map).count;
    }
    benchmark::DoNotOptimize(spots);
  }
  state.SetItemsProcessed(state.iterations() * n * n);
  state.counters["levels"] = 501;
}

std::string name(const std::string& mode, Index n, Connectivity c) {
  return "sweep/" + mode + "/n:" + std::to_string(n) + "/conn:" + std::to_string(static_cast<int>(c));
}

void register_all() {
  for (const Index n : kSizes) {
    for (const Connectivity c : kConnectivities) {
      register_timed(name("levels500", n, c), run_sweep, n, c, SweepLevels::paper(500));
      register_timed(name("exact", n, c), run_sweep, n, c, SweepLevels::exact());
      auto* slow = register_timed(name("per_level", n, c), per_level, n, c);
      if (n >= 4096) slow->Iterations(1);  // tens of seconds a run
    }
    register_timed("sweep/memory_pass/n:" + std::to_string(n), memory_pass, n);
  }
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  contactbench::bench::register_all();
  return contactbench::bench::run_benchmarks(argc, argv);
}
