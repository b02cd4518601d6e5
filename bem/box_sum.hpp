// Sums over a square window, (2 radius + 1)^2 points centred on each point of an nx x ny grid (row-major):
// wrapped at the edges when periodic, truncated (the points outside count as zero) otherwise. Running sums
// along y of whole rows (the window's rows kept in a ring small enough to stay in cache), then along x of
// each row of column sums, so the cost does not depend on the radius and the input is read once, a row at a
// time, and the output handed over a row at a time: the caller's loops over a row vectorise. The active-set
// solver's extension of the residual off the contact set is made of such sums (bem/active_set.cpp,
// docs/solvers.md "The extended filter").
#pragma once

#include <omp.h>
#include <algorithm>
#include <cstddef>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

// value_row(y, values) writes the nx inputs of row y (0 <= y < ny) to values[0 .. nx); emit_row(y, sums,
// thread) receives the window sums of row y, sums[0 .. nx), every row once, from the team's thread
// `thread`. Rows are split over `threads` threads; for a fixed thread count the sums are the same every run.
// Needs 2 radius + 1 <= nx and ny when periodic (a window that wraps onto itself would count points twice).
template <class ValueRow, class EmitRow>
void box_sum(Index nx, Index ny, Index radius, bool periodic, ValueRow value_row, EmitRow emit_row,
             std::vector<double>& scratch, int threads) {
  // The running sum along x is a chain of dependent additions: a row is cut into kChains segments, each
  // with its own running sum, so that the chains' additions overlap.
  constexpr Index kChains = 8;
  const Index window = 2 * radius + 1;
  const Index segment = (nx + kChains - 1) / kChains;
  // Per thread: the ring of the window's rows, the row entering it, the column sums, the line (the column
  // sums with radius points of margin each side: their wrapped ends, or zeros; zeros up to the last
  // chain's end) and the row of window sums.
  const std::size_t row = static_cast<std::size_t>(nx);
  const std::size_t line_size = static_cast<std::size_t>(kChains * segment + window);
  const std::size_t sums_size = static_cast<std::size_t>(kChains * segment);
  const std::size_t per_thread = (static_cast<std::size_t>(window) + 2) * row + line_size + sums_size;
  scratch.resize(per_thread * static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const Index team = omp_get_num_threads(), thread = omp_get_thread_num();
    double* const base = scratch.data() + per_thread * static_cast<std::size_t>(thread);
    std::vector<double*> ring(static_cast<std::size_t>(window));  // ring[y mod window]: row y's inputs
    for (std::size_t i = 0; i < ring.size(); ++i)
      ring[i] = base + i * row;
    double* entering = base + ring.size() * row;
    double* const column = entering + row;
    double* const line = column + row;
    double* const sums = line + line_size;
    auto slot = [&](Index y) -> double*& {
      return ring[static_cast<std::size_t>((y % window + window) % window)];
    };
    // Row y's inputs into `to`: wrapped when periodic, zeros outside the grid otherwise.
    auto load = [&](Index y, double* to) {
      if (periodic) {
        value_row((y % ny + ny) % ny, to);
      } else if (y < 0 || y >= ny) {
        std::fill(to, to + nx, 0.0);
      } else {
        value_row(y, to);
      }
    };
    const Index first = ny * thread / team, last = ny * (thread + 1) / team;
    if (first < last) {
      std::fill(column, column + nx, 0.0);
      for (Index y = first - radius; y <= first + radius; ++y) {
        double* const values = slot(y);
        load(y, values);
        for (Index x = 0; x < nx; ++x)
          column[x] += values[x];
      }
      std::fill(line, line + line_size, 0.0);
    }
    for (Index y = first; y < last; ++y) {
      // Along x: the column sums into the line between its margins, then the running sums of each segment.
      double* const middle = line + radius;
      std::copy(column, column + nx, middle);
      for (Index d = 1; d <= radius; ++d) {
        middle[-d] = periodic ? column[nx - d] : 0.0;
        middle[nx - 1 + d] = periodic ? column[d - 1] : 0.0;
      }
      double running[kChains] = {};
      for (Index c = 0; c < kChains; ++c)
        for (Index j = 0; j < window; ++j)
          running[c] += line[c * segment + j];
      for (Index i = 0; i < segment; ++i)
        for (Index c = 0; c < kChains; ++c) {
          const Index x = c * segment + i;
          sums[x] = running[c];
          running[c] += line[x + window] - line[x];
        }
      emit_row(y, static_cast<const double*>(sums), static_cast<int>(thread));
      if (y + 1 == last) break;
      // The window moves down a row: row y + radius + 1 enters the ring in the slot of row y - radius, which
      // leaves.
      load(y + radius + 1, entering);
      double*& leaving = slot(y - radius);
      for (Index x = 0; x < nx; ++x)
        column[x] += entering[x] - leaving[x];
      std::swap(entering, leaving);
    }
  }
}

}  // namespace contactbench
