// Shared pieces of the distributed tests: a deterministic field known to every rank, and this rank's rows of
// it.
#pragma once

#include <cstdint>

#include "contactbench/core/types.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi::testing {

// A smooth-plus-rough positive field on ny x nx, the same on every rank (a hash of the index, no RNG state).
inline HeightMap test_field(Index nx, Index ny, std::uint64_t salt) {
  HeightMap field(ny, nx);
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      std::uint64_t h = (static_cast<std::uint64_t>(y * nx + x) + salt) * 0x9e3779b97f4a7c15ULL;
      h ^= h >> 29;
      field(y, x) = 1.0 + static_cast<double>(h >> 11) * 0x1.0p-53;
    }
  return field;
}

// This rank's rows of a field every rank holds (tests only: real callers never hold the whole field).
inline HeightMap rows_of(const HeightMap& whole, const Slab& slab) {
  return whole.middleRows(slab.start, slab.count);
}

// max |a - b| / max |b|, on rank 0's gathered field.
inline double relative_difference(const HeightMap& a, const HeightMap& b) {
  return (a - b).abs().maxCoeff() / b.abs().maxCoeff();
}

}  // namespace contactbench::mpi::testing
