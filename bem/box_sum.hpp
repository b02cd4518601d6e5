// Sums over a square window, (2 radius + 1)^2 points centred on each point of an nx x ny grid (row-major):
// wrapped at the edges when periodic, truncated (the points outside count as zero) otherwise. Running sums
// along y of whole rows (the window's rows kept in a ring small enough to stay in cache), then along x of
// each row of column sums, so the cost does not depend on the radius and the input is read once, a row at a
// time, and the output handed over a row at a time: the caller's loops over a row vectorise. The active-set
// solver's extension of the residual off the contact set is made of such sums
// (bem/solvers/active_set_inner_cg.cpp, docs/solvers_log.md "The extended filter").
#pragma once

#include <omp.h>
#include <algorithm>
#include <cstddef>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

// The window sums of consecutive rows for one thread, made as they are asked for: sums(y, value_row) after
// sums(y - 1, ...) moves the window down a row (one row of inputs read); any other row starts afresh (the
// window's 2 radius + 1 rows read). value_row(y, values) writes the nx inputs of row y (0 <= y < ny) to
// values[0 .. nx); rows outside the grid are wrapped when periodic, zeros otherwise. So a pass that reads
// its rows in order, such as a convolution's producer, can take the sums along without a pass of its own.
// Needs 2 radius + 1 <= nx and ny when periodic (a window that wraps onto itself would count points twice).
class WindowRows {
 public:
  WindowRows() = default;
  WindowRows(Index nx, Index ny, Index radius, bool periodic)
      : nx_(nx),
        ny_(ny),
        radius_(radius),
        periodic_(periodic),
        window_(2 * radius + 1),
        segment_((nx + kChains - 1) / kChains) {
    // The ring of the window's rows, the row entering it, the column sums, the line (the column sums with
    // radius points of margin each side: their wrapped ends, or zeros; zeros up to the last chain's end)
    // and the row of window sums.
    const std::size_t row = static_cast<std::size_t>(nx);
    const std::size_t line_size = static_cast<std::size_t>(kChains * segment_ + window_);
    storage_.assign((static_cast<std::size_t>(window_) + 2) * row + line_size +
                        static_cast<std::size_t>(kChains * segment_),
                    0.0);
    ring_.resize(static_cast<std::size_t>(window_));
    for (std::size_t i = 0; i < ring_.size(); ++i)
      ring_[i] = storage_.data() + i * row;
    entering_ = storage_.data() + ring_.size() * row;
    column_ = entering_ + row;
    line_ = column_ + row;
    sums_ = line_ + line_size;
  }
  // Movable (the storage moves with its pointers into it), not copyable.
  WindowRows(const WindowRows&) = delete;
  WindowRows& operator=(const WindowRows&) = delete;
  WindowRows(WindowRows&&) = default;
  WindowRows& operator=(WindowRows&&) = default;

  // The next call starts afresh (the inputs changed).
  void restart() { current_ = kNone; }
  bool fits(Index nx, Index ny, Index radius, bool periodic) const {
    return nx == nx_ && ny == ny_ && radius == radius_ && periodic == periodic_;
  }

  // The window sums of row y, sums[0 .. nx), valid until the next call.
  template <class ValueRow>
  const double* sums(Index y, ValueRow&& value_row) {
    if (y == current_ + 1 && current_ != kNone) {
      // Down a row: row y + radius enters the ring in the slot of row y - radius - 1, which leaves.
      load(y + radius_, entering_, value_row);
      double*& leaving = slot(y - radius_ - 1);
      for (Index x = 0; x < nx_; ++x)
        column_[x] += entering_[x] - leaving[x];
      std::swap(entering_, leaving);
    } else if (y != current_) {
      std::fill(column_, column_ + nx_, 0.0);
      for (Index row = y - radius_; row <= y + radius_; ++row) {
        double* const values = slot(row);
        load(row, values, value_row);
        for (Index x = 0; x < nx_; ++x)
          column_[x] += values[x];
      }
    }
    current_ = y;
    // Along x: the column sums into the line between its margins, then the running sums of each segment
    // (kChains independent chains of additions, which overlap).
    double* const middle = line_ + radius_;
    std::copy(column_, column_ + nx_, middle);
    for (Index d = 1; d <= radius_; ++d) {
      middle[-d] = periodic_ ? column_[nx_ - d] : 0.0;
      middle[nx_ - 1 + d] = periodic_ ? column_[d - 1] : 0.0;
    }
    double running[kChains] = {};
    for (Index c = 0; c < kChains; ++c)
      for (Index j = 0; j < window_; ++j)
        running[c] += line_[c * segment_ + j];
    for (Index i = 0; i < segment_; ++i)
      for (Index c = 0; c < kChains; ++c) {
        const Index x = c * segment_ + i;
        sums_[x] = running[c];
        running[c] += line_[x + window_] - line_[x];
      }
    return sums_;
  }

 private:
  static constexpr Index kChains = 8;
  static constexpr Index kNone = -(Index(1) << 62);

  double*& slot(Index y) { return ring_[static_cast<std::size_t>((y % window_ + window_) % window_)]; }

  template <class ValueRow>
  void load(Index y, double* to, ValueRow& value_row) {
    if (periodic_) {
      value_row((y % ny_ + ny_) % ny_, to);
    } else if (y < 0 || y >= ny_) {
      std::fill(to, to + nx_, 0.0);
    } else {
      value_row(y, to);
    }
  }

  Index nx_ = 0, ny_ = 0, radius_ = 0;
  bool periodic_ = false;
  Index window_ = 1, segment_ = 0;
  Index current_ = kNone;
  std::vector<double> storage_;
  std::vector<double*> ring_;  // ring_[y mod window]: row y's inputs
  double* entering_ = nullptr;
  double* column_ = nullptr;
  double* line_ = nullptr;
  double* sums_ = nullptr;
};

// Every row's window sums: emit_row(y, sums, thread) receives those of row y, sums[0 .. nx), every row once,
// from the team's thread `thread`; value_row as for WindowRows. Rows are split over `threads` threads, each
// with its own element of `rows` (made or remade here when its shape differs); for a fixed thread count
// the sums are the same every run.
template <class ValueRow, class EmitRow>
void box_sum(Index nx, Index ny, Index radius, bool periodic, ValueRow value_row, EmitRow emit_row,
             std::vector<WindowRows>& rows, int threads) {
  if (rows.size() < static_cast<std::size_t>(threads) || !rows.front().fits(nx, ny, radius, periodic)) {
    rows.clear();
    for (int t = 0; t < threads; ++t)
      rows.emplace_back(nx, ny, radius, periodic);
  }
#pragma omp parallel num_threads(threads)
  {
    const Index team = omp_get_num_threads(), thread = omp_get_thread_num();
    WindowRows& window = rows[static_cast<std::size_t>(thread)];
    window.restart();
    const Index first = ny * thread / team, last = ny * (thread + 1) / team;
    for (Index y = first; y < last; ++y)
      emit_row(y, window.sums(y, value_row), static_cast<int>(thread));
  }
}

}  // namespace contactbench
