#include "contactbench/mpi/distributed_contact_statistics.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/labelling.hpp"

namespace contactbench::mpi {

namespace {

// Boundary edges between contact and non-contact nodes inside one slab: along x (wrapping when the topology
// does) and between its own rows (bem/contact_statistics.cpp, without the seams between slabs).
Index edges_within(const BinaryMap& contact, bool wrap_x) {
  const Index nx = contact.cols(), rows = contact.rows();
  Index edges = 0;
  if (rows == 0) return 0;
  if (nx > 1) {
    edges += (contact.rightCols(nx - 1) != contact.leftCols(nx - 1)).count();
    if (wrap_x) edges += (contact.col(0) != contact.col(nx - 1)).count();
  }
  if (rows > 1) edges += (contact.bottomRows(rows - 1) != contact.topRows(rows - 1)).count();
  return edges;
}

// A union-find over (rank, label) pairs, created on first sight; counts the unions that joined two sets.
class BorderForest {
 public:
  Index unions() const { return unions_; }
  void join(std::int64_t a, std::int64_t b) {
    const std::size_t ra = find(id(a)), rb = find(id(b));
    if (ra == rb) return;
    parent_[ra] = rb;
    ++unions_;
  }

 private:
  std::size_t id(std::int64_t key) {
    const auto [it, added] = ids_.try_emplace(key, parent_.size());
    if (added) parent_.push_back(parent_.size());
    return it->second;
  }
  std::size_t find(std::size_t i) {
    while (parent_[i] != i)
      i = parent_[i] = parent_[parent_[i]];
    return i;
  }
  std::unordered_map<std::int64_t, std::size_t> ids_;
  std::vector<std::size_t> parent_;
  Index unions_ = 0;
};

}  // namespace

ContactStatistics distributed_contact_statistics(const Grid& grid, const HeightMap& local_pressure,
                                                 const HeightMap& local_gap, const Topology& topology,
                                                 MPI_Comm comm) {
  const Slab slab = slab_of(grid, comm);
  throw_on_any_rank(local_pressure.rows() != slab.count || local_pressure.cols() != grid.nx ||
                        local_gap.rows() != slab.count || local_gap.cols() != grid.nx,
                    "mpi: contact statistics: the local pressure and gap must be this rank's slab, " +
                        std::to_string(grid.nx) + " x " + std::to_string(slab.count),
                    comm);
  const Index nx = grid.nx;
  const BinaryMap contact = (local_pressure > 0).cast<std::uint8_t>();
  Labeller labeller(Topology{topology.connectivity, topology.wrap_x, false});
  const Labelling& labelling = labeller.label(contact);

  // What rank 0 needs of each slab: its row count, spot count, and the labels of its first and last rows.
  std::vector<std::int64_t> mine(static_cast<std::size_t>(2 + 2 * nx), 0);
  mine[0] = slab.count;
  mine[1] = labelling.count;
  if (slab.count > 0) {
    for (Index x = 0; x < nx; ++x) {
      mine[static_cast<std::size_t>(2 + x)] = labelling.labels(0, x);
      mine[static_cast<std::size_t>(2 + nx + x)] = labelling.labels(slab.count - 1, x);
    }
  }
  const int ranks = size_of(comm), me = rank_of(comm);
  std::vector<std::int64_t> all(me == 0 ? mine.size() * static_cast<std::size_t>(ranks) : 0);
  MPI_Gather(mine.data(), static_cast<int>(mine.size()), MPI_INT64_T, all.data(),
             static_cast<int>(mine.size()), MPI_INT64_T, 0, comm);

  // Local sums: contact nodes, boundary edges inside the slab, the gap; for a non-periodic patch the
  // contact nodes and pressure inside the interior block (all less the outer ring of kEdgeRingPixels, as
  // bem/contact_statistics.cpp) and the whole pressure; and the largest pressure.
  const Index ring = kEdgeRingPixels;
  const bool edges = !topology.wrap_x && !topology.wrap_y && nx > 2 * ring && grid.ny > 2 * ring;
  double inside_contact = 0, inside_pressure = 0;
  if (edges) {
    const Index first = std::max(ring, slab.start), last = std::min(grid.ny - ring, slab.start + slab.count);
    for (Index y = first; y < last; ++y) {
      const Index r = y - slab.start;
      inside_contact += static_cast<double>(contact.row(r).segment(ring, nx - 2 * ring).cast<Index>().sum());
      inside_pressure += local_pressure.row(r).segment(ring, nx - 2 * ring).sum();
    }
  }
  double sums[6] = {static_cast<double>(contact.cast<Index>().sum()),
                    static_cast<double>(edges_within(contact, topology.wrap_x)),
                    local_gap.sum(),
                    inside_contact,
                    edges ? local_pressure.sum() : 0.0,
                    inside_pressure};
  MPI_Allreduce(MPI_IN_PLACE, sums, 6, MPI_DOUBLE, MPI_SUM, comm);
  double max_pressure = slab.count > 0 ? local_pressure.maxCoeff() : -std::numeric_limits<double>::infinity();
  MPI_Allreduce(MPI_IN_PLACE, &max_pressure, 1, MPI_DOUBLE, MPI_MAX, comm);

  // Rank 0: the borders between consecutive non-empty slabs, and the periodic seam from the last row to the
  // first when the topology wraps in y (a single slab then meets itself there, as the serial labeller's
  // seam).
  std::int64_t border[2] = {0, 0};  // boundary edges across borders, spots
  if (me == 0) {
    const std::size_t stride = mine.size();
    auto first_row = [&](int r, Index x) { return all[r * stride + 2 + static_cast<std::size_t>(x)]; };
    auto last_row = [&](int r, Index x) { return all[r * stride + 2 + static_cast<std::size_t>(nx + x)]; };
    std::vector<int> filled;
    std::int64_t spots = 0;
    for (int r = 0; r < ranks; ++r) {
      if (all[r * stride] > 0) filled.push_back(r);
      spots += all[r * stride + 1];
    }
    std::vector<std::pair<int, int>> borders;
    for (std::size_t i = 0; i + 1 < filled.size(); ++i)
      borders.emplace_back(filled[i], filled[i + 1]);
    if (topology.wrap_y && grid.ny > 1) borders.emplace_back(filled.back(), filled.front());
    BorderForest forest;
    const bool eight = topology.connectivity == Connectivity::eight;
    for (const auto& [upper, lower] : borders) {
      for (Index x = 0; x < nx; ++x) {
        const std::int64_t a = last_row(upper, x);
        border[0] += (a > 0) != (first_row(lower, x) > 0);
        if (a == 0) continue;
        const std::int64_t key_a = (static_cast<std::int64_t>(upper) << 40) | a;
        for (Index dx = eight ? -1 : 0; dx <= (eight ? 1 : 0); ++dx) {
          Index xb = x + dx;
          if (xb < 0 || xb >= nx) {
            if (!topology.wrap_x) continue;
            xb = (xb + nx) % nx;
          }
          const std::int64_t b = first_row(lower, xb);
          if (b > 0) forest.join(key_a, (static_cast<std::int64_t>(lower) << 40) | b);
        }
      }
    }
    border[1] = spots - forest.unions();
  }
  MPI_Bcast(border, 2, MPI_INT64_T, 0, comm);

  const Real nodes = static_cast<Real>(grid.points());
  ContactStatistics s;
  s.area_fraction = sums[0] / nodes;
  s.area_fraction_corrected =
      (sums[0] - kPerimeterCorrection * (sums[1] + static_cast<double>(border[0]))) / nodes;
  s.spots = border[1];
  s.mean_gap = sums[2] / nodes;
  s.max_pressure = max_pressure;
  if (edges) {
    if (sums[0] > 0) s.edge_contact_share = (sums[0] - sums[3]) / sums[0];
    if (sums[4] > 0) s.edge_load_share = (sums[4] - sums[5]) / sums[4];
  }
  return s;
}

}  // namespace contactbench::mpi
