// The nested coarse start's restriction on slabs (docs/mpi.md "The default solver"): the heights averaged
// over 2 x 2 blocks (bem/solvers/block_average.hpp), from this rank's slab of the fine grid to its slab of
// the coarse grid, bit-identical to the serial active_set's coarse level (ActiveSet::coarse_heights). A first
// piece of the distributed active_set; the solver itself is not distributed yet.
#pragma once

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::mpi {

// Collective. local: this rank's slab (slab_of(grid, comm)) of an nx x ny field, nx and ny even. Returns this
// rank's slab (slab_of(nx / 2, ny / 2, comm)) of the block averages. The coarse slabs are FFTW-MPI's split of
// the coarse grid, not the fine slabs halved: a fine slab of an odd number of rows (blocks of ceil(ny /
// ranks) rows) splits a block between two ranks, so the fine rows each coarse slab needs travel in one
// MPI_Alltoallv (at most a slab's rows each way).
HeightMap restrict_to_coarse_slab(const Grid& grid, const HeightMap& local, MPI_Comm comm);

}  // namespace contactbench::mpi
