// How a grid is split across the ranks of a communicator (docs/mpi.md): in slabs of whole rows, rank r owning
// rows [start, start + count) of y, the split FFTW-MPI's r2c transform asks for (fftw_mpi_local_size_2d on
// the ny x (nx/2 + 1) half spectrum: blocks of ceil(ny / ranks) rows, the last ranks possibly shorter or
// empty). Every distributed field (heights, pressure, gap) is held as its slab alone: count x nx, row-major.
#pragma once

#include <string>
#include <vector>

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::mpi {

struct Slab {
  Index nx = 0, ny = 0;  // the whole grid
  Index start = 0;       // first row this rank owns (ny when it owns none)
  Index count = 0;       // rows it owns (may be 0 when ranks outnumber blocks of rows)
  Index points() const { return count * nx; }
};

// This rank's slab of an nx x ny grid on `comm` (collective only in that every rank must agree on nx, ny).
Slab slab_of(Index nx, Index ny, MPI_Comm comm);
inline Slab slab_of(const Grid& grid, MPI_Comm comm) {
  return slab_of(grid.nx, grid.ny, comm);
}
// Every rank's slab, in rank order.
std::vector<Slab> all_slabs(Index nx, Index ny, MPI_Comm comm);

int rank_of(MPI_Comm comm);
int size_of(MPI_Comm comm);
// The ranks of comm that share this rank's machine (its memory), this one included. Collective.
int ranks_sharing_memory(MPI_Comm comm);

// For files and checks only (a rank-0 copy of the whole field is what distributing avoids):
// the whole ny x nx field on rank 0 (an empty array elsewhere) from every rank's count x nx slab.
HeightMap gather_to_root(const HeightMap& local, const Slab& slab, MPI_Comm comm);
// This rank's count x nx slab of `whole` (ny x nx, read on rank 0 only; other ranks may pass an empty array).
HeightMap scatter_from_root(const HeightMap& whole, const Slab& slab, MPI_Comm comm);

// A check that only some ranks can fail, made collective: when `failed` on any rank, every rank throws Error
// with the message of the lowest failing rank (naming it), so that no rank is left waiting in the next
// collective call. Collective.
void throw_on_any_rank(bool failed, const std::string& message, MPI_Comm comm);

// Sum of a value over the ranks (MPI_Allreduce): the one reduction the distributed solvers need.
double sum_over_ranks(double value, MPI_Comm comm);

}  // namespace contactbench::mpi
