// Internal to the sweep (core/sweep.cpp): joining horizontal stripes that were swept independently
// (docs/theory.md section 3). Each stripe counts its own components; along the seams between stripes (and the
// periodic seam in y) some of those are one component of the whole grid. This counts, as a step function of
// join time, how many the stripes counted twice.
#pragma once

#include <functional>
#include <vector>

#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench::sweep_detail {

// Rows [begin, end) of one stripe.
struct StripeRows {
  Index begin, end;
};

// After every event with time <= `time`, the stripes' counts exceed the global count by `excess`.
struct ExcessStep {
  JoinTime time;
  Index excess;
};

// Over the seam points, applies the merges each stripe saw among its seam components (`local_joins`) and
// the edges across the seams (a seam edge exists from the later join time of its two points, `time_of`), in
// time order. A seam edge that unites two sets merges two components the stripes counted apart, unless a
// later or simultaneous local merge would have united them anyway; counting all successful unions minus the
// local merges gives the excess exactly, whatever the order within one time: rank(local + seam) -
// rank(local).
std::vector<ExcessStep> seam_excess(const std::vector<std::vector<LocalJoin>>& local_joins,
                                    const std::vector<StripeRows>& stripes, const Topology& topology,
                                    Index nx, Index ny, const std::function<JoinTime(Index)>& time_of);

// Reads the excess at successive, non-decreasing times: its value after every step with time <= t.
class ExcessReader {
 public:
  ExcessReader(const std::vector<ExcessStep>& steps, std::size_t first) : steps_(steps), next_(first) {
    if (first > 0) value_ = steps[first - 1].excess;
  }
  Index at(JoinTime t) {
    while (next_ < steps_.size() && steps_[next_].time <= t)
      value_ = steps_[next_++].excess;
    return value_;
  }

 private:
  const std::vector<ExcessStep>& steps_;
  std::size_t next_;
  Index value_ = 0;
};

}  // namespace contactbench::sweep_detail
