// The geometric sweep (core/sweep.hpp, docs/theory.md section 3) of a surface given as slabs (docs/mpi.md):
// A_c(z) and N(z) at fixed levels, equal to the serial sweep's. Each rank sweeps its slab as the serial sweep
// sweeps one of its stripes (core's StripeComponents, recording the merges among the components that touch
// its first and last rows); rank 0 receives those merges and the join levels of each slab's first and last
// rows (two rows a rank, never the field) and removes the spots counted twice across the borders and the
// periodic seam exactly, with the serial sweep's seam join (core/stripe_seams.hpp) on a grid made of those
// rows only.
#pragma once

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench::mpi {

// local_heights: this rank's slab (slab_of(grid, comm)). Levels uniform or paper (every distinct height,
// SweepLevels::exact, is refused: its output alone is as large as the field). The paper's levels end at the
// mean height, here a sum over the ranks, which may round differently from the serial mean in the last bit.
// Collective; the same curve on every rank.
SweepCurve distributed_sweep(const Grid& grid, const HeightMap& local_heights, const SweepLevels& levels,
                             const Topology& topology, MPI_Comm comm);

}  // namespace contactbench::mpi
