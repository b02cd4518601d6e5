// The geometric sweep (core/sweep.hpp, docs/theory.md section 3) of a surface given as slabs (docs/mpi.md):
// A_c(z) and N(z) at fixed levels or at every distinct height, equal to the serial sweep's. Each rank sweeps
// its slab as the serial sweep sweeps one of its stripes (core's StripeComponents, recording the merges among
// the components that touch its first and last rows); rank 0 receives those merges and the join levels of
// each slab's first and last rows (two rows a rank, never the field) and removes the spots counted twice
// across the borders and the periodic seam exactly, with the serial sweep's seam join (core/stripe_seams.hpp)
// on a grid made of those rows only.
#pragma once

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench::mpi {

// local_heights: this rank's slab (slab_of(grid, comm)). Fixed levels (uniform, paper): the same curve on
// every rank; the paper's levels end at the mean height, here a sum over the ranks, which may round
// differently from the serial mean in the last bit. Every distinct height (exact): each rank sorts and sweeps
// its slab, rank 0 receives the records (one per distinct height of each slab: the only per-point data that
// travels, 16 B each) and merges them with the seams joined as above, exactly as the serial sweep merges its
// stripes; the curve, as many rows as distinct heights, is returned on rank 0 and empty elsewhere. Memory is
// checked on every rank before any work. Collective.
SweepCurve distributed_sweep(const Grid& grid, const HeightMap& local_heights, const SweepLevels& levels,
                             const Topology& topology, MPI_Comm comm);

}  // namespace contactbench::mpi
