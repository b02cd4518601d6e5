// boundary = "mirrored" on slabs (docs/mpi.md "Mirrored boundary"): the even extension of a non-periodic
// patch (app/mirrored_boundary.hpp: the record, its left-right and up-down reflections and both, 2nx x 2ny
// points) made from the patch's slabs row by row, and the patch cut back out of a field solved on the
// extension's slabs. No rank holds more than its slabs: each extension row is a patch row (y, or 2ny - 1 - y)
// moved from the rank that owns it and written forwards then backwards.
#pragma once

#include <mpi.h>

#include "contactbench/core/types.hpp"
#include "contactbench/mpi/row_exchange.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

// This rank's slab (slab_of(2nx, 2ny)) of the even extension of the nx x ny patch whose slab (slab_of(nx,
// ny)) is `patch`: the same bits as mirrored_surface's rows. Collective.
HeightMap mirrored_slab(Index nx, Index ny, const HeightMap& patch, MPI_Comm comm);

// The patch of fields solved on the extension: made once for a grid, then cut() moves, for each field, the
// first nx values of its rows y < ny into this rank's slab of the patch (slab_of(nx, ny)). Collective.
class PatchOfMirrored {
 public:
  PatchOfMirrored(Index nx, Index ny, MPI_Comm comm);

  // `extension`: this rank's slab of a field on the 2nx x 2ny grid. Collective.
  HeightMap cut(const HeightMap& extension);

 private:
  Slab patch_, extension_;
  RowExchange rows_;  // from the extension's slabs: the patch rows this rank owns
};

}  // namespace contactbench::mpi
