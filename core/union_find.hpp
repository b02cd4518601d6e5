// Union-find over integer labels in which a set's root is always its smallest member (Wu, Otoo and Suzuki
// 2009, "UFPC"): merging links the larger root under the smaller, and find halves paths as it goes.
// With roots smallest, one pass in increasing order flattens every label to a consecutive final number.
#pragma once

#include <cstdint>
#include <vector>

#include "contactbench/core/large_buffer.hpp"

namespace contactbench {

class MinRootUnionFind {
 public:
  // Room for labels [0, capacity); label 0 (the background) stays its own, final, label 0.
  void reset(std::size_t capacity) {
    parent_.resize(capacity);
    parent_[0] = 0;
  }

  std::int32_t make_set(std::int32_t label) {
    parent_[label] = label;
    return label;
  }
  std::int32_t find(std::int32_t label) {
    while (parent_[label] != label) {
      parent_[label] = parent_[parent_[label]];  // path halving keeps parent <= child
      label = parent_[label];
    }
    return label;
  }
  // Joins the sets of a and b; returns the root of the union.
  std::int32_t merge(std::int32_t a, std::int32_t b) {
    a = find(a);
    b = find(b);
    if (a < b) return parent_[b] = a;
    return parent_[a] = b;
  }
  // Labels [first, last) in increasing order: each root gets the next final number (after `count`), every
  // other label its root's number. Ranges must be flattened in increasing order of their labels.
  void flatten(std::int32_t first, std::int32_t last, std::int32_t& count) {
    for (std::int32_t label = first; label < last; ++label)
      parent_[label] = parent_[label] == label ? ++count : parent_[parent_[label]];
  }
  // After flatten: the final number of a label.
  std::int32_t final_label(std::int32_t label) const { return parent_[label]; }

 private:
  LargeBuffer<std::int32_t> parent_;
};

}  // namespace contactbench
