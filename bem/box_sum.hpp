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
  // The index of i + step on a line of n points, or -1 outside a non-periodic line.
  auto at = [periodic](Index i, Index n) -> Index {
    if (periodic) return (i % n + n) % n;
    return i >= 0 && i < n ? i : -1;
  };
#pragma omp parallel num_threads(threads)
  {
    // Along x: each row copied into a line with radius points of margin each side (its wrapped ends, or
    // zeros), then one running sum.
    std::vector<double> line(static_cast<std::size_t>(nx + 2 * radius + 1), 0.0);
#pragma omp for schedule(static)
    for (Index y = 0; y < ny; ++y) {
      const std::size_t row = static_cast<std::size_t>(y * nx);
      double* const middle = line.data() + radius;
      for (Index x = 0; x < nx; ++x)
        middle[x] = static_cast<double>(value(row + static_cast<std::size_t>(x)));
      for (Index d = 1; d <= radius; ++d) {
        middle[-d] = periodic ? middle[nx - d] : 0.0;
        middle[nx - 1 + d] = periodic ? middle[d - 1] : 0.0;
      }
      double sum = 0;
      for (Index j = 0; j <= 2 * radius; ++j)
        sum += line[static_cast<std::size_t>(j)];
      double* const out = along_x + row;
      for (Index x = 0; x < nx; ++x) {
        out[x] = sum;
        sum += line[static_cast<std::size_t>(x + 2 * radius + 1)] - line[static_cast<std::size_t>(x)];
      }
    }
    // Along y: each thread a block of rows, a running sum of whole rows.
    const Index team = omp_get_num_threads(), thread = omp_get_thread_num();
    const Index first = ny * thread / team, last = ny * (thread + 1) / team;
    std::vector<double> sum(static_cast<std::size_t>(nx), 0.0);
    auto add_row = [&](Index y, double sign) {
      const Index j = at(y, ny);
      if (j < 0) return;
      const double* const source = along_x + j * nx;
      for (Index x = 0; x < nx; ++x)
        sum[static_cast<std::size_t>(x)] += sign * source[x];
    };
    if (first < last)
      for (Index d = -radius; d <= radius; ++d)
        add_row(first + d, 1.0);
    for (Index y = first; y < last; ++y) {
      for (Index x = 0; x < nx; ++x)
        emit(static_cast<std::size_t>(y * nx + x), sum[static_cast<std::size_t>(x)],
             static_cast<int>(thread));
      if (y + 1 < last) {
        add_row(y + radius + 1, 1.0);
        add_row(y - radius, -1.0);
      }
    }
  }
}

}  // namespace contactbench
