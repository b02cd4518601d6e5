// Rows of a slab-split field that a rank needs from other ranks (docs/mpi.md "The default solver"): the
// halo of a window sum (the kExtensionRadius rows above and below a slab, wrapped when periodic) or the
// coarse rows an interpolation reads. Which global rows each rank needs is fixed when the exchange is made;
// each exchange() then moves them in one MPI_Alltoallv, from whichever ranks own them (a slab thinner than
// the halo gets its rows from further ranks), and row(y) reads any needed row or any row of one's own slab.
#pragma once

#include <functional>
#include <vector>

#include <mpi.h>

#include "contactbench/core/types.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

class RowExchange {
 public:
  // Collective in that every rank must make it with the same layout and `needs`. `layout`: every rank's slab
  // of the field (all_slabs), nx values a row; needs(rank): the global rows that rank reads (any order,
  // duplicates and its own rows allowed, each in [0, ny)).
  RowExchange(const std::vector<Slab>& layout, int rank, const std::function<std::vector<Index>(int)>& needs,
              MPI_Comm comm);

  // The rows of a window of `radius` rows about each row of the slab: [start - radius, start + count +
  // radius), wrapped when periodic, cut at the edges otherwise.
  static RowExchange halo(const std::vector<Slab>& layout, int rank, Index radius, bool periodic,
                          MPI_Comm comm);

  // Moves the needed rows: `mine` is this rank's slab (count x nx, row-major), which row() then also reads
  // (it must stay alive and unchanged while row() is used). Collective.
  void exchange(const double* mine);
  // The same with the rows others need made by fill(local_row, out) (nx values each) rather than read from a
  // stored slab; row() then gives received rows only (nullptr for this rank's own). Collective.
  void exchange(const std::function<void(Index, double*)>& fill);
  // Global row y: from this rank's slab or received; nullptr when it is neither.
  const double* row(Index y) const;

 private:
  Slab slab_;
  MPI_Comm comm_;
  const double* mine_ = nullptr;
  std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
  std::vector<Index> send_rows_;  // local indices of own rows, in send order
  std::vector<double> send_buffer_, receive_buffer_;
  std::vector<Index> received_at_;  // per global row: its index in receive_buffer_ (in rows), or -1
};

}  // namespace contactbench::mpi
