// Connected-component labelling of a binary map: contact spots of {h > z} or of a BEM contact map.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "contactbench/core/topology.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// Non-zero (1 by convention) = foreground, in contact; 0 = background. Row-major like HeightMap (rows are y).
using BinaryMap = Eigen::Array<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
// 0 = background, 1..count = component; row-major like HeightMap.
using LabelMap = Eigen::Array<std::int32_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct Labelling {
  LabelMap labels;
  Index count = 0;           // number of components
  std::vector<Index> areas;  // areas[k - 1]: points in component k
};

// Labels binary maps of any size with one topology, keeping its buffers from one call to the next (a BEM
// load curve or a benchmark labels many maps of one shape). Two-pass labelling with union-find, parallel
// over horizontal stripes whose borders (and the periodic seams) are merged afterwards: for 4-connectivity a
// scan point by point (the decision tree of SAUF, Wu, Otoo and Suzuki 2009, reduced to its two neighbours),
// for 8-connectivity a scan of runs of two-row bands on rows packed into bits (BMRS, Lee et al. 2021).
// Components are numbered in raster order of their first point (4-connectivity) or of their first 2 x 2
// block (8-connectivity; a block never holds two components), whatever the thread count.
class Labeller {
 public:
  explicit Labeller(Topology topology, int threads = 1);
  ~Labeller();
  Labeller(Labeller&&) noexcept;
  Labeller& operator=(Labeller&&) noexcept;

  // The labelling of `map`, valid until the next call.
  const Labelling& label(const BinaryMap& map);
  // The same, handing over the result (the next call allocates anew).
  Labelling take(const BinaryMap& map);

  const Topology& topology() const { return topology_; }

 private:
  struct Buffers;
  Topology topology_;
  int threads_;
  std::unique_ptr<Buffers> buffers_;
};

// One labelling with a fresh Labeller: (SAUF's decision tree for 8-connectivity, Wu, Otoo and Suzuki 2009),
// parallel over horizontal stripes whose borders (and the periodic seams) are merged afterwards.
// Labels are numbered in raster order of each component's first point, whatever the thread count.
Labelling label_components(const BinaryMap& map, const Topology& topology, int threads = 1);

// The set {h > z} (strictly above, docs/theory.md section 3).
BinaryMap threshold_above(const HeightMap& heights, Real z);

}  // namespace contactbench
