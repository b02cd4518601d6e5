#include "contactbench/mpi/distributed_restriction.hpp"

#include <algorithm>
#include <climits>
#include <string>
#include <vector>

#include "contactbench/bem/solvers/block_average.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/mpi/message_count.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchanges are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kRestrictionExchange = "the coarse level's restriction";

// Rows [start, start + count) intersected with [other_start, other_start + other_count): how many.
Index overlap(Index start, Index count, Index other_start, Index other_count) {
  return std::max<Index>(0,
                         std::min(start + count, other_start + other_count) - std::max(start, other_start));
}

}  // namespace

HeightMap restrict_to_coarse_slab(const Grid& grid, const HeightMap& local, MPI_Comm comm) {
  const Index nx = grid.nx, ny = grid.ny;
  if (nx % 2 != 0 || ny % 2 != 0)
    throw Error("mpi: the 2 x 2 restriction needs an even grid, got " + std::to_string(nx) + " x " +
                std::to_string(ny));
  const Slab fine = slab_of(nx, ny, comm);
  throw_on_any_rank(local.rows() != fine.count || local.cols() != nx,
                    "mpi: the restriction's slab is " + std::to_string(local.rows()) + " x " +
                        std::to_string(local.cols()) + ", expected " + std::to_string(fine.count) + " x " +
                        std::to_string(nx),
                    comm);
  const std::vector<Slab> fine_slabs = all_slabs(nx, ny, comm);
  const std::vector<Slab> coarse_slabs = all_slabs(nx / 2, ny / 2, comm);
  const Slab& coarse = coarse_slabs[static_cast<std::size_t>(rank_of(comm))];
  // Each coarse slab needs the fine rows [2 start, 2 (start + count)); rows travel whole, in order.
  const std::size_t ranks = fine_slabs.size();
  std::vector<int> send_counts(ranks), send_offsets(ranks), receive_counts(ranks), receive_offsets(ranks);
  for (std::size_t r = 0; r < ranks; ++r) {
    const Slab& needs = coarse_slabs[r];
    const Index sent = overlap(fine.start, fine.count, 2 * needs.start, 2 * needs.count);
    send_counts[r] = message_count(sent * nx, kRestrictionExchange);
    send_offsets[r] = message_count(sent > 0 ? (std::max(fine.start, 2 * needs.start) - fine.start) * nx : 0,
                                    kRestrictionExchange);
    const Slab& has = fine_slabs[r];
    const Index received = overlap(has.start, has.count, 2 * coarse.start, 2 * coarse.count);
    receive_counts[r] = message_count(received * nx, kRestrictionExchange);
    receive_offsets[r] =
        message_count(received > 0 ? (std::max(has.start, 2 * coarse.start) - 2 * coarse.start) * nx : 0,
                      kRestrictionExchange);
  }
  std::vector<double> fine_rows(static_cast<std::size_t>(std::max<Index>(2 * coarse.count * nx, 1)));
  MPI_Alltoallv(local.data(), send_counts.data(), send_offsets.data(), MPI_DOUBLE, fine_rows.data(),
                receive_counts.data(), receive_offsets.data(), MPI_DOUBLE, comm);
  const std::vector<double> averages = block_averages(fine_rows.data(), nx, coarse.count);
  HeightMap out(coarse.count, nx / 2);
  std::copy(averages.begin(), averages.end(), out.data());
  return out;
}

}  // namespace contactbench::mpi
