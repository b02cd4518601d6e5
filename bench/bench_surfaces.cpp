#include "bench/bench_surfaces.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <vector>

#include "core/generation.hpp"

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

}  // namespace contactbench::bench
