// Sums over a square window, (2 radius + 1)^2 points centred on each point of an nx x ny grid (row-major):
// wrapped at the edges when periodic, truncated (the points outside count as zero) otherwise. Running sums
// along x, then along y, so the cost does not depend on the radius; the sums along x of the rows a window
// spans are kept in a ring of rows small enough to stay in cache, so the input is read once and no
// full-size intermediate array is written. The active-set solver's extension of the residual off the
// contact set is made of such sums (bem/active_set.cpp, docs/solvers.md "The extended filter").
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
  // Per thread: the line of four rows side by side with their margins, the ring of rows' sums along x
  // (the window's rows and the four computed ahead) and the running sums along y.
  constexpr Index kLanes = 4;
  const Index window = 2 * radius + 1, slots = window + kLanes;
  const std::size_t line_size = static_cast<std::size_t>((nx + window) * kLanes);
  const std::size_t per_thread = line_size + static_cast<std::size_t>((slots + 1) * nx);
  scratch.resize(per_thread * static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const Index team = omp_get_num_threads(), thread = omp_get_thread_num();
    double* const line = scratch.data() + per_thread * static_cast<std::size_t>(thread);
    double* const ring = line + line_size;
    double* const sum = ring + slots * nx;
    auto slot = [&](Index y) { return ring + ((y % slots + slots) % slots) * nx; };
    // Sums along x of rows y0 .. y0 + 3 (wrapped when periodic, zeros outside the grid otherwise) into
    // their slots: interleaved in the line with radius points of margin each side (their wrapped ends, or
    // zeros), then four running sums side by side (independent chains: a single running sum waits on its
    // own additions).
    auto along_x = [&](Index y0) {
      double* const middle = line + radius * kLanes;  // middle[x * kLanes + lane]
      for (Index lane = 0; lane < kLanes; ++lane) {
        const Index y = periodic ? ((y0 + lane) % ny + ny) % ny : y0 + lane;
        const bool inside = y >= 0 && y < ny;
        const std::size_t row = static_cast<std::size_t>(y * nx);
        for (Index x = 0; x < nx; ++x)
          middle[x * kLanes + lane] =
              inside ? static_cast<double>(value(row + static_cast<std::size_t>(x))) : 0.0;
        for (Index d = 1; d <= radius; ++d) {
          middle[-d * kLanes + lane] = periodic ? middle[(nx - d) * kLanes + lane] : 0.0;
          middle[(nx - 1 + d) * kLanes + lane] = periodic ? middle[(d - 1) * kLanes + lane] : 0.0;
        }
      }
      double running[kLanes] = {};
      for (Index j = 0; j < window; ++j)
        for (Index lane = 0; lane < kLanes; ++lane)
          running[lane] += line[j * kLanes + lane];
      double* out[kLanes];
      for (Index lane = 0; lane < kLanes; ++lane)
        out[lane] = slot(y0 + lane);
      const double* const enter = line + window * kLanes;
      for (Index x = 0; x + 1 < nx; ++x)
        for (Index lane = 0; lane < kLanes; ++lane) {
          out[lane][x] = running[lane];
          running[lane] += enter[x * kLanes + lane] - line[x * kLanes + lane];
        }
      for (Index lane = 0; lane < kLanes; ++lane)
        out[lane][nx - 1] = running[lane];
    };
    // Along y: each thread a block of rows, a running sum of whole rows; the rows' sums along x computed
    // four at a time as the window reaches them (a block's first window computes its own radius rows above).
    const Index first = ny * thread / team, last = ny * (thread + 1) / team;
    Index computed = first - radius;  // the next row whose sums along x are to be made
    auto reach = [&](Index y) {
      for (; computed <= y; computed += kLanes)
        along_x(computed);
    };
    if (first < last) {
      reach(first + radius);
      for (Index x = 0; x < nx; ++x)
        sum[x] = 0;
      for (Index d = -radius; d <= radius; ++d) {
        const double* const source = slot(first + d);
        for (Index x = 0; x < nx; ++x)
          sum[x] += source[x];
      }
    }
    for (Index y = first; y < last; ++y) {
      for (Index x = 0; x < nx; ++x)
        emit(static_cast<std::size_t>(y * nx + x), sum[x], static_cast<int>(thread));
      if (y + 1 == last) break;
      // The window moves down a row: the row below it enters, its top row leaves.
      reach(y + radius + 1);
      const double* const enter = slot(y + radius + 1);
      const double* const leave = slot(y - radius);
      for (Index x = 0; x < nx; ++x)
        sum[x] += enter[x] - leave[x];
    }
  }
}

}  // namespace contactbench
