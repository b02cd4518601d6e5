#include "contactbench/core/sweep.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/stripe_seams.hpp"
#include "contactbench/core/sweep_exact.hpp"
#include "contactbench/core/sweep_levels.hpp"

namespace contactbench {

using sweep_detail::append_level;
using sweep_detail::empty_sweep_curve;
using sweep_detail::ExcessReader;
using sweep_detail::ExcessStep;
using sweep_detail::fixed_levels;
using sweep_detail::join_time;
using sweep_detail::JoinTime;
using sweep_detail::kNever;
using sweep_detail::LocalJoin;
using sweep_detail::SharedForest;
using sweep_detail::StripeComponents;
using sweep_detail::StripeHistory;
using sweep_detail::StripeReader;
using sweep_detail::StripeRecord;
using sweep_detail::StripeRows;
using sweep_detail::sweep_stripe_exact;
using sweep_detail::sweep_stripe_levels;

std::uintmax_t sweep_memory_bytes(Index points, const SweepLevels& levels, int threads) {
  const auto n = static_cast<std::uintmax_t>(std::max<Index>(points, 0));
  if (levels.kind == SweepLevels::Kind::exact) return saturating_product(n, 8 + 16 + 24 + 32);
  const auto stripes = static_cast<std::uintmax_t>(std::max(threads, 1));
  const auto count = saturating_sum(static_cast<std::uintmax_t>(std::max<Index>(levels.count, 0)), 2);
  return saturating_sum(saturating_product(n, 8 + 4),
                        saturating_product(count, saturating_sum(8 + 32, saturating_product(stripes, 32))));
}

std::optional<SweepLevels> SweepLevels::named(std::string_view name) {
  if (name == "exact") return exact();
  if (name == "paper") return paper();
  return std::nullopt;
}

std::optional<SweepLevels> SweepLevels::counted(std::int64_t count) {
  if (count >= 1) return uniform(static_cast<Index>(count));
  return std::nullopt;
}

std::optional<Connectivity> connectivity_of(std::int64_t neighbours) {
  if (neighbours == 4) return Connectivity::four;
  if (neighbours == 8) return Connectivity::eight;
  return std::nullopt;
}

SweepCurve sweep(const Surface& surface, const SweepLevels& levels, const Topology& topology, int threads) {
  const HeightMap& heights = surface.heights();
  const Index nx = surface.nx(), ny = surface.ny(), n = heights.size();
  if (n >= SharedForest::kMaxPoints)
    throw Error("sweep: " + std::to_string(n) + " points are more than the sweep's limit of 2^30");
  check_fits_in_memory(
      sweep_memory_bytes(n, levels, threads),
      "the sweep of " + std::to_string(n) + " points" +
          (levels.kind == SweepLevels::Kind::exact ? std::string(" at every distinct height")
                                                   : " at " + std::to_string(levels.count) + " levels"));
  const bool exact = levels.kind == SweepLevels::Kind::exact;
  // Fixed levels: from the highest height down to the lowest, or (paper) to the mean plane.
  const std::vector<Real> fixed_z =
      exact ? std::vector<Real>{}
            : fixed_levels(heights.maxCoeff(),
                           levels.kind == SweepLevels::Kind::paper ? heights.mean() : heights.minCoeff(),
                           levels.count);
  const int team = team_size(n, threads);

  // When a point joins {h > z}: its height's descending key (exact) or its level index (kNever: never).
  const Real* h = heights.data();
  auto time_of = [&](Index i) { return join_time(h[i], exact, fixed_z); };

  // Horizontal stripes, one per thread (as many as asked, whatever the size, so that the joining logic is
  // the same for all sizes); each is swept on its own with its own part of one union-find array.
  const Index stripe_count = std::clamp<Index>(threads, 1, ny);
  std::vector<StripeRows> rows(static_cast<std::size_t>(stripe_count));
  for (Index s = 0; s < stripe_count; ++s)
    rows[s] = {s * ny / stripe_count, (s + 1) * ny / stripe_count};
  const bool seams = stripe_count > 1;
  SharedForest forest(n, seams);
  std::vector<StripeComponents> stripes;
  for (Index s = 0; s < stripe_count; ++s)
    stripes.emplace_back(forest, nx, ny, rows[s].begin, rows[s].end, topology,
                         seams && (s > 0 || topology.wrap_y),
                         seams && (s + 1 < stripe_count || topology.wrap_y));

#pragma omp parallel for num_threads(std::min <int>(team, static_cast <int>(stripe_count))) \
    schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    const Index first = rows[s].begin * nx, last = rows[s].end * nx;
    if (exact)
      sweep_stripe_exact(heights, first, last, stripes[s]);
    else
      sweep_stripe_levels(heights, fixed_z, first, last, stripes[s]);
  }

  std::vector<std::vector<LocalJoin>> local_joins;
  for (auto& stripe : stripes)
    local_joins.push_back(std::move(stripe.local_joins()));
  const std::vector<ExcessStep> excess_steps = seam_excess(local_joins, rows, topology, nx, ny, time_of);

  // The global curve: at each level, the stripes' counts less the components they counted twice.
  SweepCurve curve = empty_sweep_curve(surface.grid(), levels, topology);
  if (exact) {
    std::vector<StripeHistory> histories;
    for (auto& stripe : stripes)
      histories.push_back({std::move(stripe.records()), stripe.components(), stripe.points()});
    sweep_detail::merge_exact_levels(histories, excess_steps, n, team, curve);
  } else {
    ExcessReader excess(excess_steps, 0);
    std::vector<StripeReader> readers;
    for (auto& stripe : stripes)
      readers.emplace_back(stripe.records(), stripe.components(), stripe.points());
    for (std::size_t k = 0; k < fixed_z.size(); ++k) {
      Index components = 0, points = 0;
      for (StripeReader& reader : readers) {
        reader.advance(k);
        components += reader.components();
        points += reader.points();
      }
      append_level(curve, fixed_z[k], points, components - excess.at(k), n);
    }
  }
  return curve;
}

}  // namespace contactbench
