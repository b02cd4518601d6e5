#include "contactbench/core/stripe_seams.hpp"

#include <algorithm>
#include <numeric>

namespace contactbench::sweep_detail {

namespace {

// A small union-find over the points of the seam rows.
class SeamForest {
 public:
  explicit SeamForest(Index size) : parent_(static_cast<std::size_t>(size)) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  bool unite(Index a, Index b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent_[std::max(a, b)] = std::min(a, b);
    return true;
  }

 private:
  Index find(Index i) {
    while (parent_[i] != i)
      i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  std::vector<Index> parent_;
};

}  // namespace

std::vector<ExcessStep> seam_excess(const std::vector<std::vector<LocalJoin>>& local_joins,
                                    const std::vector<StripeRows>& stripes, const Topology& topology,
                                    Index nx, Index ny, const std::function<JoinTime(Index)>& time_of) {
  std::vector<ExcessStep> steps;
  if (stripes.size() < 2) return steps;
  // Seam rows and their compact numbering.
  std::vector<Index> slot(static_cast<std::size_t>(ny), -1);
  Index slots = 0;
  auto add_row = [&](Index y) {
    if (slot[y] < 0) slot[y] = slots++;
  };
  struct Seam {
    Index upper, lower;  // the last row of one stripe and the first row of the next
  };
  std::vector<Seam> seams;
  for (std::size_t s = 0; s < stripes.size(); ++s) {
    if (s + 1 == stripes.size() && !topology.wrap_y) break;
    const StripeRows& next = stripes[(s + 1) % stripes.size()];
    seams.push_back({stripes[s].end - 1, next.begin});
    add_row(stripes[s].end - 1);
    add_row(next.begin);
  }
  auto id = [&](Index i) { return slot[i / nx] * nx + i % nx; };

  struct Event {
    JoinTime time;
    Index a, b;
    bool local;
  };
  std::vector<Event> events;
  for (const auto& joins : local_joins)
    for (const LocalJoin& join : joins)
      events.push_back({join.time, id(join.a), id(join.b), true});
  for (const Seam& seam : seams)
    for (Index x = 0; x < nx; ++x) {
      auto edge = [&](Index x_lower) {
        const Index p = seam.upper * nx + x, q = seam.lower * nx + x_lower;
        const JoinTime tp = time_of(p), tq = time_of(q);
        if (tp != kNever && tq != kNever) events.push_back({std::max(tp, tq), id(p), id(q), false});
      };
      edge(x);
      if (topology.connectivity == Connectivity::eight) {
        if (x > 0 || topology.wrap_x) edge((x + nx - 1) % nx);
        if (x + 1 < nx || topology.wrap_x) edge((x + 1) % nx);
      }
    }
  std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.time < b.time; });

  SeamForest forest(slots * nx);
  Index excess = 0;
  for (std::size_t e = 0; e < events.size(); ++e) {
    // A local merge always counts against the excess (the stripe already counted it); a union succeeds
    // or not.
    excess += (forest.unite(events[e].a, events[e].b) ? 1 : 0) - (events[e].local ? 1 : 0);
    if (e + 1 == events.size() || events[e + 1].time != events[e].time)
      steps.push_back({events[e].time, excess});
  }
  return steps;
}

}  // namespace contactbench::sweep_detail
