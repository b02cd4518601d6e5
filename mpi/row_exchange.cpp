#include "contactbench/mpi/row_exchange.hpp"

#include <algorithm>
#include <climits>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/mpi/message_count.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchanges are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kRowExchange = "a row exchange";

// The rank owning global row y (slabs in rank order), or -1.
int owner_of(const std::vector<Slab>& layout, Index y) {
  for (std::size_t r = 0; r < layout.size(); ++r)
    if (y >= layout[r].start && y < layout[r].start + layout[r].count) return static_cast<int>(r);
  return -1;
}

// The rows `rank` needs from others, sorted, without duplicates or its own rows.
std::vector<Index> foreign_rows(const std::vector<Slab>& layout, int rank,
                                const std::function<std::vector<Index>(int)>& needs) {
  const Slab& own = layout[static_cast<std::size_t>(rank)];
  std::vector<Index> rows = needs(rank);
  for (const Index y : rows)
    if (y < 0 || y >= own.ny)
      throw Error("mpi: a row exchange asks for row " + std::to_string(y) + " of a grid of " +
                  std::to_string(own.ny) + " rows");
  std::erase_if(rows, [&](Index y) { return y >= own.start && y < own.start + own.count; });
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

}  // namespace

RowExchange::RowExchange(const std::vector<Slab>& layout, int rank,
                         const std::function<std::vector<Index>(int)>& needs, MPI_Comm comm)
    : slab_(layout[static_cast<std::size_t>(rank)]), comm_(comm) {
  const std::size_t ranks = layout.size();
  const Index nx = slab_.nx;
  received_at_.assign(static_cast<std::size_t>(slab_.ny), -1);
  // What this rank receives: its foreign rows grouped by owner (owners in rank order, rows sorted within).
  const std::vector<Index> wanted = foreign_rows(layout, rank, needs);
  std::vector<std::vector<Index>> from(ranks);
  for (const Index y : wanted)
    from[static_cast<std::size_t>(owner_of(layout, y))].push_back(y);
  Index received = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    receive_counts_.push_back(message_count(static_cast<Index>(from[r].size()) * nx, kRowExchange));
    receive_offsets_.push_back(message_count(received * nx, kRowExchange));
    for (const Index y : from[r])
      received_at_[static_cast<std::size_t>(y)] = received++;
  }
  // What it sends: its own rows each other rank wants, in that rank's order (the same computation there).
  Index sent = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    Index rows = 0;
    if (static_cast<int>(r) != rank && layout[r].count > 0)
      for (const Index y : foreign_rows(layout, static_cast<int>(r), needs))
        if (y >= slab_.start && y < slab_.start + slab_.count) {
          send_rows_.push_back(y - slab_.start);
          ++rows;
        }
    send_counts_.push_back(message_count(rows * nx, kRowExchange));
    send_offsets_.push_back(message_count(sent * nx, kRowExchange));
    sent += rows;
  }
  send_buffer_.resize(static_cast<std::size_t>(std::max<Index>(sent * nx, 1)));
  receive_buffer_.resize(static_cast<std::size_t>(std::max<Index>(received * nx, 1)));
}

RowExchange RowExchange::halo(const std::vector<Slab>& layout, int rank, Index radius, bool periodic,
                              MPI_Comm comm) {
  auto needs = [&](int r) {
    const Slab& s = layout[static_cast<std::size_t>(r)];
    std::vector<Index> rows;
    if (s.count == 0) return rows;
    for (Index y = s.start - radius; y < s.start + s.count + radius; ++y) {
      if (periodic)
        rows.push_back(((y % s.ny) + s.ny) % s.ny);
      else if (y >= 0 && y < s.ny)
        rows.push_back(y);
    }
    return rows;
  };
  return RowExchange(layout, rank, needs, comm);
}

void RowExchange::exchange(const double* mine) {
  mine_ = mine;
  const Index nx = slab_.nx;
  for (std::size_t i = 0; i < send_rows_.size(); ++i)
    std::copy_n(mine + send_rows_[i] * nx, nx, send_buffer_.data() + static_cast<Index>(i) * nx);
  MPI_Alltoallv(send_buffer_.data(), send_counts_.data(), send_offsets_.data(), MPI_DOUBLE,
                receive_buffer_.data(), receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE, comm_);
}

void RowExchange::exchange(const std::function<void(Index, double*)>& fill) {
  mine_ = nullptr;
  const Index nx = slab_.nx;
  for (std::size_t i = 0; i < send_rows_.size(); ++i)
    fill(send_rows_[i], send_buffer_.data() + static_cast<Index>(i) * nx);
  MPI_Alltoallv(send_buffer_.data(), send_counts_.data(), send_offsets_.data(), MPI_DOUBLE,
                receive_buffer_.data(), receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE, comm_);
}

const double* RowExchange::row(Index y) const {
  if (y >= slab_.start && y < slab_.start + slab_.count)
    return mine_ ? mine_ + (y - slab_.start) * slab_.nx : nullptr;
  const Index at = received_at_[static_cast<std::size_t>(y)];
  return at < 0 ? nullptr : receive_buffer_.data() + at * slab_.nx;
}

}  // namespace contactbench::mpi
