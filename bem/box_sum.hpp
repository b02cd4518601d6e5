// Sums over a square window, (2 radius + 1)^2 points centred on each point of an nx x ny grid (row-major):
// wrapped at the edges when periodic, truncated (the points outside count as zero) otherwise. Two passes of
// running sums, along x into a scratch array, then along y, so the cost does not depend on the radius. The
// active-set solver's extension of the residual off the contact set is made of such sums (bem/active_set.cpp,
// docs/solvers.md "The extended filter").
#pragma once

#include <omp.h>
#include <algorithm>
#include <cstddef>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

// value(k) gives the input at point k (a double); emit(k, sum, thread) receives the window's sum at k,
// every point once, from the team's thread `thread`. Rows are split over `threads` threads; for a fixed
// thread count the sums are the same every run. Needs 2 radius + 1 <= nx and ny when periodic (a window that
// wraps onto itself would count points twice).
template <class Value, class Emit>
void box_sum(Index nx, Index ny, Index radius, bool periodic, Value value, Emit emit,
             std::vector<double>& scratch, int threads) {
  scratch.resize(static_cast<std::size_t>(nx * ny));
  double* const along_x = scratch.data();
  // The index of point i of a line of n points: wrapped when periodic, -1 outside the line otherwise.
  auto at = [periodic](Index i, Index n) -> Index {
    if (periodic) return (i % n + n) % n;
    return i >= 0 && i < n ? i : -1;
  };
#pragma omp parallel num_threads(threads)
  {
    // Along x: four rows at a time, interleaved in a line with radius points of margin each side (their
    // wrapped ends, or zeros), then four running sums side by side (independent chains: a single running
    // sum waits on its own additions).
    constexpr Index kLanes = 4;
    std::vector<double> line(static_cast<std::size_t>((nx + 2 * radius + 1) * kLanes), 0.0);
    const Index groups = (ny + kLanes - 1) / kLanes;
#pragma omp for schedule(static)
    for (Index group = 0; group < groups; ++group) {
      const Index y0 = group * kLanes, rows = std::min(kLanes, ny - y0);
      double* const middle = line.data() + radius * kLanes;  // middle[x * kLanes + lane]
      for (Index lane = 0; lane < kLanes; ++lane) {
        const std::size_t row = static_cast<std::size_t>((y0 + lane) * nx);
        for (Index x = 0; x < nx; ++x)
          middle[x * kLanes + lane] =
              lane < rows ? static_cast<double>(value(row + static_cast<std::size_t>(x))) : 0.0;
        for (Index d = 1; d <= radius; ++d) {
          middle[-d * kLanes + lane] = periodic ? middle[(nx - d) * kLanes + lane] : 0.0;
          middle[(nx - 1 + d) * kLanes + lane] = periodic ? middle[(d - 1) * kLanes + lane] : 0.0;
        }
      }
      double sum[kLanes] = {};
      for (Index j = 0; j <= 2 * radius; ++j)
        for (Index lane = 0; lane < kLanes; ++lane)
          sum[lane] += line[static_cast<std::size_t>(j * kLanes + lane)];
      const double* const enter = line.data() + (2 * radius + 1) * kLanes;
      const double* const leave = line.data();
      for (Index x = 0; x < nx; ++x) {
        for (Index lane = 0; lane < rows; ++lane)
          along_x[(y0 + lane) * nx + x] = sum[lane];
        for (Index lane = 0; lane < kLanes; ++lane)
          sum[lane] += enter[x * kLanes + lane] - leave[x * kLanes + lane];
      }
    }
    // Along y: each thread a block of rows, a running sum of whole rows.
    const Index team = omp_get_num_threads(), thread = omp_get_thread_num();
    const Index first = ny * thread / team, last = ny * (thread + 1) / team;
    std::vector<double> sum(static_cast<std::size_t>(nx), 0.0), zeros(static_cast<std::size_t>(nx), 0.0);
    auto row_at = [&](Index y) -> const double* {  // a row of zeros outside a non-periodic grid
      const Index j = at(y, ny);
      return j < 0 ? zeros.data() : along_x + j * nx;
    };
    if (first < last)
      for (Index d = -radius; d <= radius; ++d) {
        const double* const source = row_at(first + d);
        for (Index x = 0; x < nx; ++x)
          sum[static_cast<std::size_t>(x)] += source[x];
      }
    for (Index y = first; y < last; ++y) {
      for (Index x = 0; x < nx; ++x)
        emit(static_cast<std::size_t>(y * nx + x), sum[static_cast<std::size_t>(x)],
             static_cast<int>(thread));
      if (y + 1 == last) break;
      // The window moves down a row: the row below it enters, its top row leaves (either may be outside).
      const double* const enter = row_at(y + radius + 1);
      const double* const leave = row_at(y - radius);
      for (Index x = 0; x < nx; ++x)
        sum[static_cast<std::size_t>(x)] += enter[x] - leave[x];
    }
  }
}

}  // namespace contactbench
