// The nested coarse start's restriction (docs/solvers.md "The active-set method"): a field averaged over
// 2 x 2 blocks, the next coarser level's heights. One kernel for the serial method
// (active_set_coarse_start.cpp) and the distributed one (mpi/distributed_restriction.hpp), which must agree
// bit for bit.
#pragma once

#include <cstddef>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

// From `fine_rows` = 2 x coarse_ny rows of nx points (row-major, nx even): coarse_ny rows of nx / 2 block
// averages, each summed in double in the order (2y, 2x), (2y, 2x + 1), (2y + 1, 2x), (2y + 1, 2x + 1).
template <class T>
std::vector<T> block_averages(const T* fine_rows, Index nx, Index coarse_ny) {
  const Index cnx = nx / 2;
  std::vector<T> coarse(static_cast<std::size_t>(cnx * coarse_ny));
  auto at = [&](Index y, Index x) {
    return static_cast<double>(fine_rows[static_cast<std::size_t>(y * nx + x)]);
  };
  for (Index y = 0; y < coarse_ny; ++y)
    for (Index x = 0; x < cnx; ++x)
      coarse[static_cast<std::size_t>(y * cnx + x)] = static_cast<T>(
          0.25 * (at(2 * y, 2 * x) + at(2 * y, 2 * x + 1) + at(2 * y + 1, 2 * x) + at(2 * y + 1, 2 * x + 1)));
  return coarse;
}

}  // namespace contactbench
