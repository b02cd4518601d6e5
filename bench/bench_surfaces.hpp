// Surfaces and binary maps the benchmarks share: made by the project's own generator, seeded, cached.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "contactbench/core/labelling.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench::bench {

// Threads every benchmark runs on (the project's target machine has two cores).
inline constexpr int kThreads = 2;

// The paper's surface A spectrum (sigma 0.5 um, H 0.5, qr 3.14e4 1/m) on n x n points over 200 um, qs at
// the Nyquist wavevector of that grid: roughness down to the pixel, the hard case for labelling.
const Surface& rough_surface(Index n);

// {h > z} of rough_surface(n) with z chosen so that `coverage` (a fraction) of the points lie above.
const BinaryMap& contact_map(Index n, double coverage);

// The physical floor every harness reports against: one pass that reads the n x n heights and writes one
// int32 per point, on kThreads threads.
void memory_pass(benchmark::State& state, Index n);

// Registers `name` running fn(state, args...), reported as every harness reports: wall time (the work runs on
// kThreads threads, so CPU time would count each second twice), in milliseconds.
template <typename Fn, typename... Args>
benchmark::internal::Benchmark* register_timed(const std::string& name, Fn&& fn, Args&&... args) {
  return benchmark::RegisterBenchmark(name.c_str(), std::forward<Fn>(fn), std::forward<Args>(args)...)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
}

// Initialises Google Benchmark, records the thread count and `context` in its output, runs what is
// registered. Returns the process status.
int run_benchmarks(int argc, char** argv,
                   const std::vector<std::pair<std::string, std::string>>& context = {});

}  // namespace contactbench::bench
