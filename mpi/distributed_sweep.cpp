#include "contactbench/mpi/distributed_sweep.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/stripe_seams.hpp"
#include "contactbench/core/sweep_exact.hpp"
#include "contactbench/core/sweep_levels.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

using sweep_detail::ExcessReader;
using sweep_detail::JoinTime;
using sweep_detail::kNever;
using sweep_detail::LocalJoin;
using sweep_detail::SharedForest;
using sweep_detail::StripeComponents;
using sweep_detail::StripeHistory;
using sweep_detail::StripeReader;
using sweep_detail::StripeRecord;
using sweep_detail::StripeRows;

namespace {

// Rank 0 receives every rank's records of the exact sweep (point to point: a rank's count fits an int, the
// sum may not).
std::vector<StripeHistory> gather_histories(const StripeHistory& mine, const std::vector<int>& stripe_ranks,
                                            MPI_Comm comm) {
  constexpr int kTag = 71;
  static_assert(sizeof(StripeRecord) == 16);
  const int me = rank_of(comm);
  std::vector<StripeHistory> histories;
  if (me != 0) {
    if (std::find(stripe_ranks.begin(), stripe_ranks.end(), me) != stripe_ranks.end()) {
      const std::int64_t finals[3] = {static_cast<std::int64_t>(mine.records.size()), mine.components,
                                      mine.points};
      MPI_Send(finals, 3, MPI_INT64_T, 0, kTag, comm);
      MPI_Send(mine.records.data(), static_cast<int>(mine.records.size() * sizeof(StripeRecord)), MPI_BYTE, 0,
               kTag, comm);
    }
    return histories;
  }
  for (const int r : stripe_ranks) {
    if (r == 0) {
      histories.push_back(mine);
      continue;
    }
    std::int64_t finals[3];
    MPI_Recv(finals, 3, MPI_INT64_T, r, kTag, comm, MPI_STATUS_IGNORE);
    StripeHistory history{std::vector<StripeRecord>(static_cast<std::size_t>(finals[0])), finals[1],
                          finals[2]};
    MPI_Recv(history.records.data(), static_cast<int>(history.records.size() * sizeof(StripeRecord)),
             MPI_BYTE, r, kTag, comm, MPI_STATUS_IGNORE);
    histories.push_back(std::move(history));
  }
  return histories;
}

}  // namespace

SweepCurve distributed_sweep(const Grid& grid, const HeightMap& local_heights, const SweepLevels& levels,
                             const Topology& topology, MPI_Comm comm) {
  const bool exact = levels.kind == SweepLevels::Kind::exact;
  const Index nx = grid.nx;
  const auto slabs = all_slabs(nx, grid.ny, comm);
  const int ranks = size_of(comm), me = rank_of(comm);
  const Slab& slab = slabs[static_cast<std::size_t>(me)];
  throw_on_any_rank(local_heights.rows() != slab.count || local_heights.cols() != nx,
                    "distributed sweep: the local heights are " + std::to_string(local_heights.cols()) +
                        " x " + std::to_string(local_heights.rows()) + " but this rank's slab is " +
                        std::to_string(nx) + " x " + std::to_string(slab.count),
                    comm);
  throw_on_any_rank(slab.points() >= SharedForest::kMaxPoints,
                    "distributed sweep: a slab of " + std::to_string(slab.points()) +
                        " points is more than the sweep's limit of 2^30 a rank: use more ranks",
                    comm);
  // Memory, before any work: each rank its slab's sweep; with exact levels rank 0 also every rank's records
  // (16 B a distinct height) and the curve (32 B a row), as many rows as distinct heights.
  {
    std::uintmax_t need = sweep_memory_bytes(slab.points(), levels, 1);
    if (exact && me == 0) need = saturating_sum(need, saturating_product(grid.points(), 16 + 32));
    const std::uintmax_t available = available_memory_bytes();
    throw_on_any_rank(
        available > 0 && need > available,
        "distributed sweep: rank " + std::to_string(me) + " needs about " + format_bytes(need) +
            (exact && me == 0 ? " (the curve at every distinct height is gathered there)" : "") +
            "; this machine has " + format_bytes(available) + " available",
        comm);
  }

  // Fixed levels, from the whole surface's extremes (or mean), as the serial sweep takes them.
  std::vector<Real> z;
  const bool filled = slab.count > 0;
  if (!exact) {
    double extremes[2] = {filled ? local_heights.maxCoeff() : -std::numeric_limits<double>::infinity(),
                          filled ? -local_heights.minCoeff() : -std::numeric_limits<double>::infinity()};
    MPI_Allreduce(MPI_IN_PLACE, extremes, 2, MPI_DOUBLE, MPI_MAX, comm);
    const Real bottom = levels.kind == SweepLevels::Kind::paper
                            ? sum_over_ranks(local_heights.sum(), comm) / static_cast<Real>(grid.points())
                            : -extremes[1];
    z = sweep_detail::fixed_levels(extremes[0], bottom, levels.count);
  }
  const Index level_count = static_cast<Index>(z.size());
  // When a point of this height joins {h > z}: its descending key (exact) or its level.
  auto time_of_height = [&](Real height) { return sweep_detail::join_time(height, exact, z); };

  // The slabs that hold rows, in order: each is a stripe of the serial sweep.
  std::vector<int> stripes_of_ranks;
  int my_stripe = -1;
  for (int r = 0; r < ranks; ++r)
    if (slabs[static_cast<std::size_t>(r)].count > 0) {
      if (r == me) my_stripe = static_cast<int>(stripes_of_ranks.size());
      stripes_of_ranks.push_back(r);
    }
  const int stripe_count = static_cast<int>(stripes_of_ranks.size());
  const bool seams = stripe_count > 1;

  // This rank's stripe: its counts per level (fixed) or its records (exact), its merges among seam
  // components, its seam rows' join times.
  std::vector<std::int64_t> counts(static_cast<std::size_t>(2 * level_count), 0);   // components, points
  StripeHistory history;                                                            // exact levels
  std::vector<std::int64_t> joins;                                                  // (time, a, b) triples
  std::vector<std::uint64_t> seam_times(static_cast<std::size_t>(2 * nx), kNever);  // first row, last row
  if (filled) {
    const Index rows = slab.count;
    // A single stripe is the whole grid and wraps in y itself; otherwise the seams do.
    const Topology local{topology.connectivity, topology.wrap_x, seams ? false : topology.wrap_y};
    SharedForest forest(slab.points(), seams);
    StripeComponents stripe(forest, nx, rows, 0, rows, local, seams && (my_stripe > 0 || topology.wrap_y),
                            seams && (my_stripe + 1 < stripe_count || topology.wrap_y));
    if (exact) {
      sweep_detail::sweep_stripe_exact(local_heights, 0, slab.points(), stripe);
      history = {std::move(stripe.records()), stripe.components(), stripe.points()};
    } else {
      sweep_detail::sweep_stripe_levels(local_heights, z, 0, slab.points(), stripe);
      StripeReader reader(stripe.records(), stripe.components(), stripe.points());
      for (Index k = 0; k < level_count; ++k) {
        reader.advance(static_cast<JoinTime>(k));
        counts[static_cast<std::size_t>(k)] = reader.components();
        counts[static_cast<std::size_t>(level_count + k)] = reader.points();
      }
    }
    for (const LocalJoin& join : stripe.local_joins()) {
      joins.push_back(static_cast<std::int64_t>(join.time));
      joins.push_back(join.a);
      joins.push_back(join.b);
    }
    for (Index x = 0; x < nx; ++x) {
      seam_times[static_cast<std::size_t>(x)] = time_of_height(local_heights(0, x));
      seam_times[static_cast<std::size_t>(nx + x)] = time_of_height(local_heights(rows - 1, x));
    }
  }
  std::vector<std::int64_t> totals(me == 0 ? counts.size() : 0);
  MPI_Reduce(counts.data(), totals.data(), static_cast<int>(counts.size()), MPI_INT64_T, MPI_SUM, 0, comm);
  std::vector<std::uint64_t> all_times(me == 0 ? seam_times.size() * static_cast<std::size_t>(ranks) : 0);
  MPI_Gather(seam_times.data(), static_cast<int>(seam_times.size()), MPI_UINT64_T, all_times.data(),
             static_cast<int>(seam_times.size()), MPI_UINT64_T, 0, comm);
  const int my_joins = static_cast<int>(joins.size());
  std::vector<int> join_counts(static_cast<std::size_t>(ranks)),
      join_offsets(static_cast<std::size_t>(ranks), 0);
  MPI_Gather(&my_joins, 1, MPI_INT, join_counts.data(), 1, MPI_INT, 0, comm);
  for (int r = 1; r < ranks; ++r)
    join_offsets[r] = join_offsets[r - 1] + join_counts[r - 1];
  std::vector<std::int64_t> all_joins(
      me == 0 ? static_cast<std::size_t>(join_offsets.back() + join_counts.back()) : 0);
  MPI_Gatherv(joins.data(), my_joins, MPI_INT64_T, all_joins.data(), join_counts.data(), join_offsets.data(),
              MPI_INT64_T, 0, comm);
  const std::vector<StripeHistory> histories =
      exact ? gather_histories(history, stripes_of_ranks, comm) : std::vector<StripeHistory>{};

  SweepCurve curve = sweep_detail::empty_sweep_curve(grid, levels, topology);
  // Rank 0: the seams, on a grid of the stripes' first and last rows only (one row for a stripe of one row),
  // with core's seam join; the spots are the stripes' counts less the components counted twice.
  std::vector<std::int64_t> spots(static_cast<std::size_t>(level_count), 0);
  if (me == 0) {
    std::vector<StripeRows> rows;
    std::vector<std::pair<int, int>> row_source;  // per virtual row: (rank, 0 first row / 1 last row)
    std::vector<std::vector<LocalJoin>> local_joins;
    for (const int r : stripes_of_ranks) {
      const Index count = slabs[static_cast<std::size_t>(r)].count;
      const Index begin = static_cast<Index>(row_source.size());
      row_source.emplace_back(r, 0);
      if (count > 1) row_source.emplace_back(r, 1);
      rows.push_back({begin, static_cast<Index>(row_source.size())});
      // A local point (its slab's first or last row) as a point of the seam grid.
      auto seam_point = [&](std::int64_t local) {
        const Index row = static_cast<Index>(local) / nx, x = static_cast<Index>(local) % nx;
        return static_cast<std::int32_t>((begin + (row == 0 ? 0 : 1)) * nx + x);
      };
      std::vector<LocalJoin> mine;
      for (int j = join_offsets[r]; j < join_offsets[r] + join_counts[r]; j += 3)
        mine.push_back({static_cast<JoinTime>(all_joins[j]), seam_point(all_joins[j + 1]),
                        seam_point(all_joins[j + 2])});
      local_joins.push_back(std::move(mine));
    }
    const Index seam_rows = static_cast<Index>(row_source.size());
    auto time_of = [&](Index point) -> JoinTime {
      const auto [rank, which] = row_source[static_cast<std::size_t>(point / nx)];
      return all_times[static_cast<std::size_t>(rank) * 2 * nx + which * nx + point % nx];
    };
    const auto steps = sweep_detail::seam_excess(local_joins, rows, topology, nx, seam_rows, time_of);
    if (exact) {
      // The whole curve, on rank 0 only: as many rows as distinct heights.
      sweep_detail::merge_exact_levels(histories, steps, grid.points(), 1, curve);
      return curve;
    }
    ExcessReader excess(steps, 0);
    for (Index k = 0; k < level_count; ++k)
      spots[static_cast<std::size_t>(k)] =
          totals[static_cast<std::size_t>(k)] - excess.at(static_cast<JoinTime>(k));
    counts.assign(totals.begin() + level_count, totals.end());  // points per level
  }
  if (exact) return curve;  // the other ranks: empty
  counts.resize(static_cast<std::size_t>(level_count));
  MPI_Bcast(spots.data(), static_cast<int>(level_count), MPI_INT64_T, 0, comm);
  MPI_Bcast(counts.data(), static_cast<int>(level_count), MPI_INT64_T, 0, comm);

  for (Index k = 0; k < level_count; ++k)
    sweep_detail::append_level(curve, z[static_cast<std::size_t>(k)], counts[static_cast<std::size_t>(k)],
                               spots[static_cast<std::size_t>(k)], grid.points());
  return curve;
}

}  // namespace contactbench::mpi
