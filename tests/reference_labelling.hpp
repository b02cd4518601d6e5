// A deliberately simple reference for connected-component labelling and the sweep (docs/theory.md section 3):
// breadth-first flood fill over the grid graph that a Topology defines. No union-find, no stripes, no
// decision tree: each foreground point not yet reached starts a new component, visited in raster order,
// so component ids also come out in raster order of each component's first point.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <vector>

#include "contactbench/core/labelling.hpp"
#include "contactbench/core/topology.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::reference {

struct ReferenceLabelling {
  Index count = 0;        // number of components
  std::vector<Index> id;  // per point, row-major (iy * nx + ix): -1 = background, else 0..count-1
};

// The neighbours of (iy, ix) on an ny x nx grid: out-of-range neighbours wrap (modular indexing) when the
// topology wraps that direction and are dropped otherwise. On 1- or 2-wide grids a neighbour may be the
// point itself or the same point twice; the flood fill does not care (a visited point is skipped).
struct Neighbours {
  std::array<Index, 8> point{};  // row-major indices iy * nx + ix
  int size = 0;
};

inline Neighbours neighbours(Index iy, Index ix, Index ny, Index nx, const Topology& topology) {
  Neighbours result;
  const bool eight = topology.connectivity == Connectivity::eight;
  for (Index dy = -1; dy <= 1; ++dy)
    for (Index dx = -1; dx <= 1; ++dx) {
      if (dy == 0 && dx == 0) continue;
      if (!eight && dy != 0 && dx != 0) continue;  // 4-connectivity: no diagonals
      Index y = iy + dy, x = ix + dx;
      if (y < 0 || y >= ny) {
        if (!topology.wrap_y) continue;
        y = (y + ny) % ny;
      }
      if (x < 0 || x >= nx) {
        if (!topology.wrap_x) continue;
        x = (x + nx) % nx;
      }
      result.point[static_cast<std::size_t>(result.size++)] = y * nx + x;
    }
  return result;
}

inline ReferenceLabelling reference_labelling(const BinaryMap& map, const Topology& topology) {
  const Index ny = map.rows(), nx = map.cols();
  ReferenceLabelling out;
  out.id.assign(static_cast<std::size_t>(ny * nx), -1);
  std::deque<Index> queue;
  for (Index start = 0; start < ny * nx; ++start) {  // raster order
    if (map(start / nx, start % nx) == 0 || out.id[static_cast<std::size_t>(start)] >= 0) continue;
    const Index component = out.count++;
    out.id[static_cast<std::size_t>(start)] = component;
    queue.push_back(start);
    while (!queue.empty()) {
      const Index p = queue.front();
      queue.pop_front();
      const Neighbours next = neighbours(p / nx, p % nx, ny, nx, topology);
      for (int k = 0; k < next.size; ++k) {
        const Index q = next.point[static_cast<std::size_t>(k)];
        if (map(q / nx, q % nx) == 0 || out.id[static_cast<std::size_t>(q)] >= 0) continue;
        out.id[static_cast<std::size_t>(q)] = component;
        queue.push_back(q);
      }
    }
  }
  return out;
}

// The set {h > z}, strictly above, by the obvious loop.
inline BinaryMap reference_threshold(const HeightMap& heights, Real z) {
  BinaryMap map(heights.rows(), heights.cols());
  for (Index iy = 0; iy < heights.rows(); ++iy)
    for (Index ix = 0; ix < heights.cols(); ++ix)
      map(iy, ix) = heights(iy, ix) > z ? 1 : 0;
  return map;
}

struct ReferenceLevel {
  Index points = 0;      // points with h > z
  Index components = 0;  // connected components of {h > z}
};

// A_c (as a point count) and N of {h > z} by thresholding and flood-filling: one level, from scratch.
inline ReferenceLevel reference_sweep_at(const HeightMap& heights, Real z, const Topology& topology) {
  const BinaryMap map = reference_threshold(heights, z);
  ReferenceLevel level;
  for (Index iy = 0; iy < map.rows(); ++iy)
    for (Index ix = 0; ix < map.cols(); ++ix)
      level.points += map(iy, ix);
  level.components = reference_labelling(map, topology).count;
  return level;
}

}  // namespace contactbench::reference
