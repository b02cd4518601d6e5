// bem/contact_statistics.hpp on slabs (docs/mpi.md): the real contact area by nodes and perimeter-corrected,
// the number of contact spots, the mean gap and the largest pressure of a distributed solution, equal to the
// serial statistics of the same fields. The boundary edges and spots that cross slab borders (and the
// periodic seam in y) are found from each slab's first and last rows: each rank labels its own slab (core's
// Labeller, not wrapping in y), and rank 0 joins the labels that touch across each border with a union-find,
// as the sweep joins its stripes; the spots are the slabs' counts less the joins.
#pragma once

#include <mpi.h>

#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/topology.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

// local_pressure and local_gap: this rank's slab (slab_of(grid, comm)) of the solution; contact is p > 0.
// `topology` decides connectivity and wrap-around, as the serial labeller's. Collective; the same result on
// every rank.
ContactStatistics distributed_contact_statistics(const Grid& grid, const HeightMap& local_pressure,
                                                 const HeightMap& local_gap, const Topology& topology,
                                                 MPI_Comm comm);

}  // namespace contactbench::mpi
