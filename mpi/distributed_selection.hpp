// The k-th largest of values spread over the ranks, exactly: what the cold start of the active-set method
// takes from its candidates' scores in one process with std::nth_element (ActiveSet::coarse_area_level,
// docs/solvers.md "The active-set method"), here without gathering them. A piece of the distributed
// active_set (docs/mpi.md "The default solver"); the solver itself is not distributed yet.
#pragma once

#include <cstddef>
#include <vector>

#include <mpi.h>

namespace contactbench::mpi {

// Collective. The k-th largest (k from 1) of the union of every rank's `values` (finite), the same on every
// rank and whatever the split: a radix selection on the values' bit patterns in order, one byte a pass, each
// pass an MPI_Allreduce of a 256-bin histogram (8 passes). Equal to what std::nth_element with
// std::greater finds in the union (0 and -0, equal as values, may come back either way). Throws Error on
// every rank when k is 0 or above the union's size.
double kth_largest_over_ranks(const std::vector<double>& values, std::size_t k, MPI_Comm comm);

}  // namespace contactbench::mpi
