#include "contactbench/mpi/distributed_sweep.hpp"

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/stripe_components.hpp"
#include "contactbench/core/stripe_seams.hpp"
#include "contactbench/core/sweep_levels.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

using sweep_detail::ExcessReader;
using sweep_detail::JoinTime;
using sweep_detail::kNever;
using sweep_detail::LocalJoin;
using sweep_detail::SharedForest;
using sweep_detail::StripeComponents;
using sweep_detail::StripeReader;
using sweep_detail::StripeRows;

SweepCurve distributed_sweep(const Grid& grid, const HeightMap& local_heights, const SweepLevels& levels,
                             const Topology& topology, MPI_Comm comm) {
  if (levels.kind == SweepLevels::Kind::exact)
    throw Error(
        "distributed sweep: levels at every distinct height (exact) are not distributed (docs/mpi.md); "
        "use uniform or paper levels");
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

  // The levels, from the whole surface's extremes (or mean), as the serial sweep takes them.
  const bool filled = slab.count > 0;
  double extremes[2] = {filled ? local_heights.maxCoeff() : -std::numeric_limits<double>::infinity(),
                        filled ? -local_heights.minCoeff() : -std::numeric_limits<double>::infinity()};
  MPI_Allreduce(MPI_IN_PLACE, extremes, 2, MPI_DOUBLE, MPI_MAX, comm);
  const Real bottom = levels.kind == SweepLevels::Kind::paper
                          ? sum_over_ranks(local_heights.sum(), comm) / static_cast<Real>(grid.points())
                          : -extremes[1];
  const std::vector<Real> z = sweep_detail::fixed_levels(extremes[0], bottom, levels.count);
  const Index level_count = static_cast<Index>(z.size());

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

  // This rank's stripe: its counts per level, its merges among seam components, its seam rows' join levels.
  std::vector<std::int64_t> counts(static_cast<std::size_t>(2 * level_count), 0);   // components, points
  std::vector<std::int64_t> joins;                                                  // (time, a, b) triples
  std::vector<std::uint64_t> seam_times(static_cast<std::size_t>(2 * nx), kNever);  // first row, last row
  if (filled) {
    const Index rows = slab.count;
    // A single stripe is the whole grid and wraps in y itself; otherwise the seams do.
    const Topology local{topology.connectivity, topology.wrap_x, seams ? false : topology.wrap_y};
    SharedForest forest(slab.points(), seams);
    StripeComponents stripe(forest, nx, rows, 0, rows, local, seams && (my_stripe > 0 || topology.wrap_y),
                            seams && (my_stripe + 1 < stripe_count || topology.wrap_y));
    sweep_detail::sweep_stripe_levels(local_heights, z, 0, slab.points(), stripe);
    StripeReader reader(stripe.records(), stripe.components(), stripe.points());
    for (Index k = 0; k < level_count; ++k) {
      reader.advance(static_cast<JoinTime>(k));
      counts[static_cast<std::size_t>(k)] = reader.components();
      counts[static_cast<std::size_t>(level_count + k)] = reader.points();
    }
    for (const LocalJoin& join : stripe.local_joins()) {
      joins.push_back(static_cast<std::int64_t>(join.time));
      joins.push_back(join.a);
      joins.push_back(join.b);
    }
    for (Index x = 0; x < nx; ++x) {
      seam_times[static_cast<std::size_t>(x)] = sweep_detail::joining_level(local_heights(0, x), z);
      seam_times[static_cast<std::size_t>(nx + x)] =
          sweep_detail::joining_level(local_heights(rows - 1, x), z);
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
    ExcessReader excess(steps, 0);
    for (Index k = 0; k < level_count; ++k)
      spots[static_cast<std::size_t>(k)] =
          totals[static_cast<std::size_t>(k)] - excess.at(static_cast<JoinTime>(k));
    counts.assign(totals.begin() + level_count, totals.end());  // points per level
  }
  counts.resize(static_cast<std::size_t>(level_count));
  MPI_Bcast(spots.data(), static_cast<int>(level_count), MPI_INT64_T, 0, comm);
  MPI_Bcast(counts.data(), static_cast<int>(level_count), MPI_INT64_T, 0, comm);

  SweepCurve curve;
  curve.topology = topology;
  curve.levels = levels;
  curve.nominal_area = grid.nominal_area();
  const Real points_total = static_cast<Real>(grid.points());
  for (Index k = 0; k < level_count; ++k) {
    curve.z.push_back(z[static_cast<std::size_t>(k)]);
    curve.points.push_back(counts[static_cast<std::size_t>(k)]);
    curve.spots.push_back(spots[static_cast<std::size_t>(k)]);
    curve.area_fraction.push_back(static_cast<Real>(counts[static_cast<std::size_t>(k)]) / points_total);
  }
  return curve;
}

}  // namespace contactbench::mpi
