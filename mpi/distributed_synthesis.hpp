// A real field on slabs from its half spectrum given column by column, bit-identical to core's serial
// synthesis (core/fft.hpp, ReproducibleInverseFft2d): the pipeline the distributed generator and the
// distributed Fourier refinement share (docs/mpi.md).
#pragma once

#include <functional>

#include <mpi.h>

#include "contactbench/core/types.hpp"

namespace contactbench::mpi {

// The kx columns [first, last) of an nx-wide grid's half spectrum (nx/2 + 1 columns) whose values this rank
// gives: whole chunks of the serial synthesis (ReproducibleInverseFft2d::kLinesPerChunk columns), split
// evenly over the ranks; empty on ranks beyond the chunks.
struct SpectrumColumns {
  Index first = 0, last = 0;
  Index count() const { return last - first; }
};
SpectrumColumns synthesis_columns(Index nx, int rank, int ranks);

// Writes the half spectrum's values of kx columns [first, first + width) (width at most one chunk), all ny
// rows, into `block` as ny x width, row-major. Called once a chunk, in increasing column order.
using SpectrumColumnFill = std::function<void(Index first, Index width, Complex* block)>;

// This rank's slab (slab_of(nx, ny, comm), count x nx) of the field out(x) = sum_k in_k exp(+i q_k.x) whose
// half spectrum `fill` gives for this rank's columns (synthesis_columns): the serial transform's rows bit for
// bit whatever the number of ranks. Each rank transforms its chunks along y with the serial plans' shapes;
// one all-to-all turns the columns into row slabs, which each rank transforms along x. Collective.
HeightMap synthesize_slab(Index nx, Index ny, const SpectrumColumnFill& fill, MPI_Comm comm);

}  // namespace contactbench::mpi
