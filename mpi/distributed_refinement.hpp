// Fourier refinement on slabs (docs/mpi.md): the scene's surface on a finer grid without any rank holding
// the finer grid whole.
#pragma once

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/surface.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::mpi {

// The finer grid (core's refine: the surface's sizes, nx x ny points, periodic) and this rank's slab of it.
struct RefinedSlab {
  Grid grid;
  HeightMap local;  // slab_of(grid, comm): count x nx
};

// This rank's slab of core's refine(surface, nx, ny, threads)
// (core/generation.hpp): the serial refinement's rows bit for bit, whatever the number of ranks. Rank 0
// passes the surface to refine and the finer grid's size; the other ranks nullptr (their nx, ny are not
// read). Rank 0 takes the surface's Fourier coefficients with the serial code on `threads` (so the same bits
// as one process), sends each rank the columns of them its chunks of the finer half spectrum hold (at most
// 16 B a point of the surface in all), and the ranks synthesise the finer grid on their slabs as the serial
// refinement embeds and transforms it (mpi/distributed_synthesis.hpp). Collective; the serial refinement's
// refusals (a non-periodic surface, a coarser target) are thrown on every rank.
RefinedSlab refine_surface_slab(const Surface* root_surface, Index nx, Index ny, int threads, MPI_Comm comm);

}  // namespace contactbench::mpi
