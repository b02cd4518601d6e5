// The bit patterns of a height map, row by row, so that -0.0 and 0.0 differ and a comparison of two surfaces
// is truly bit for bit (the lossless round trips of the topography files).
#pragma once

#include <bit>
#include <cstdint>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench::testing {

inline std::vector<std::uint64_t> bits_of(const HeightMap& heights) {
  std::vector<std::uint64_t> bits;
  for (Index row = 0; row < heights.rows(); ++row)
    for (Index column = 0; column < heights.cols(); ++column)
      bits.push_back(std::bit_cast<std::uint64_t>(heights(row, column)));
  return bits;
}

}  // namespace contactbench::testing
