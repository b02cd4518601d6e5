#include "core/labelling.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/union_find.hpp"

namespace contactbench {

namespace {

// Rows [first, last) of the map, labelled by one thread with provisional labels from [base, ...).
struct Stripe {
  Index first = 0, last = 0;
  std::int32_t base = 0, next = 0;
};

// First pass over one stripe: provisional labels, equivalences recorded in `sets`. A row's upper neighbours
// are only looked at inside the stripe; the stripe's first row is joined to the row above it later.
template <Connectivity connectivity>
void first_pass(const BinaryMap& map, LabelMap& labels, MinRootUnionFind& sets, Stripe& stripe) {
  const Index nx = map.cols();
  std::int32_t next = stripe.base;
  for (Index y = stripe.first; y < stripe.last; ++y) {
    const std::uint8_t* row = map.data() + y * nx;
    const std::uint8_t* up = y > stripe.first ? row - nx : nullptr;
    std::int32_t* label = labels.data() + y * nx;
    const std::int32_t* label_up = up ? label - nx : nullptr;  // no pointer before the array
    for (Index x = 0; x < nx; ++x) {
      if (!row[x]) {
        label[x] = 0;
        continue;
      }
      const bool left = x > 0 && row[x - 1];
      if constexpr (connectivity == Connectivity::four) {
        const bool above = up && up[x];
        if (above && left)
          label[x] = label_up[x] == label[x - 1] ? label[x - 1] : sets.merge(label_up[x], label[x - 1]);
        else if (above)
          label[x] = label_up[x];
        else if (left)
          label[x] = label[x - 1];
        else
          label[x] = sets.make_set(next++);
      } else {
        // SAUF's decision tree (Wu, Otoo, Suzuki 2009) on the mask p q r / s x: q touches p, r and s, so
        // q alone decides; otherwise r may need joining to p or s, which do not touch r.
        const bool q = up && up[x];
        const bool r = up && x + 1 < nx && up[x + 1];
        const bool p = up && x > 0 && up[x - 1];
        if (q)
          label[x] = label_up[x];
        else if (r && p)
          label[x] = sets.merge(label_up[x + 1], label_up[x - 1]);
        else if (r && left)
          label[x] = sets.merge(label_up[x + 1], label[x - 1]);
        else if (r)
          label[x] = label_up[x + 1];
        else if (p)
          label[x] = label_up[x - 1];
        else if (left)
          label[x] = label[x - 1];
        else
          label[x] = sets.make_set(next++);
      }
    }
  }
  stripe.next = next;
}

// Joins the points of row y to their neighbours in row y_above, which the first pass did not look at:
// the first row of every stripe, and row 0 to row ny-1 across a periodic seam.
void join_rows(const BinaryMap& map, const LabelMap& labels, MinRootUnionFind& sets, const Topology& topology,
               Index y, Index y_above) {
  const Index nx = map.cols();
  auto join = [&](Index x, Index x_above) {
    if (map(y_above, x_above)) sets.merge(labels(y, x), labels(y_above, x_above));
  };
  for (Index x = 0; x < nx; ++x) {
    if (!map(y, x)) continue;
    join(x, x);
    if (topology.connectivity == Connectivity::eight) {
      if (x > 0 || topology.wrap_x) join(x, (x + nx - 1) % nx);
      if (x + 1 < nx || topology.wrap_x) join(x, (x + 1) % nx);
    }
  }
}

// Joins column 0 to column nx-1 across the periodic seam in x (and its diagonals for 8-connectivity).
void join_columns_across_seam(const BinaryMap& map, const LabelMap& labels, MinRootUnionFind& sets,
                              const Topology& topology) {
  const Index nx = map.cols(), ny = map.rows(), last = nx - 1;
  auto join = [&](Index y1, Index x1, Index y2, Index x2) {
    if (map(y1, x1) && map(y2, x2)) sets.merge(labels(y1, x1), labels(y2, x2));
  };
  for (Index y = 0; y < ny; ++y) {
    join(y, 0, y, last);
    if (topology.connectivity == Connectivity::eight && (y > 0 || topology.wrap_y)) {
      const Index y_above = (y + ny - 1) % ny;
      join(y, 0, y_above, last);
      join(y, last, y_above, 0);
    }
  }
}

}  // namespace

struct Labeller::Buffers {
  Labelling result;
  MinRootUnionFind sets;
  std::vector<std::vector<Index>> stripe_areas;
};

Labeller::Labeller(Topology topology, int threads)
    : topology_(topology), threads_(std::max(threads, 1)), buffers_(std::make_unique<Buffers>()) {}
Labeller::~Labeller() = default;
Labeller::Labeller(Labeller&&) noexcept = default;
Labeller& Labeller::operator=(Labeller&&) noexcept = default;

Labelling Labeller::take(const BinaryMap& map) {
  label(map);
  return std::exchange(buffers_->result, Labelling{});
}

const Labelling& Labeller::label(const BinaryMap& map) {
  const Index nx = map.cols(), ny = map.rows();
  Labelling& result = buffers_->result;
  MinRootUnionFind& sets = buffers_->sets;
  result.labels.resize(ny, nx);
  result.count = 0;
  result.areas.clear();
  if (nx < 1 || ny < 1) return result;
  // A row holds at most ceil(nx/2) new labels (a new label needs background to its left).
  const Index labels_per_row = (nx + 1) / 2;
  if (static_cast<double>(ny) * static_cast<double>(labels_per_row) >= 2147483647.0)
    throw Error("labelling: a " + std::to_string(nx) + " x " + std::to_string(ny) +
                " map may need more labels than 32-bit integers hold");

  const Index stripe_count = std::clamp<Index>(threads_, 1, ny);
  std::vector<Stripe> stripes(stripe_count);
  for (Index s = 0; s < stripe_count; ++s) {
    stripes[s].first = s * ny / stripe_count;
    stripes[s].last = (s + 1) * ny / stripe_count;
    stripes[s].base = static_cast<std::int32_t>(1 + stripes[s].first * labels_per_row);
  }
  sets.reset(static_cast<std::size_t>(1 + ny * labels_per_row));

  // Stripes follow the thread count (so the result and the seams are the same for any size); only maps
  // large enough to pay for a parallel region get one.
  const int team = nx * ny >= kMinPointsForThreads ? static_cast<int>(stripe_count) : 1;
#pragma omp parallel for num_threads(team) schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    if (topology_.connectivity == Connectivity::four)
      first_pass<Connectivity::four>(map, result.labels, sets, stripes[s]);
    else
      first_pass<Connectivity::eight>(map, result.labels, sets, stripes[s]);
  }

  // Seams between stripes and periodic seams: a few rows and two columns, done by one thread.
  for (Index s = 1; s < stripe_count; ++s)
    join_rows(map, result.labels, sets, topology_, stripes[s].first, stripes[s].first - 1);
  if (topology_.wrap_y) join_rows(map, result.labels, sets, topology_, 0, ny - 1);
  if (topology_.wrap_x) join_columns_across_seam(map, result.labels, sets, topology_);

  std::int32_t count = 0;
  for (const Stripe& stripe : stripes)
    sets.flatten(stripe.base, stripe.next, count);
  result.count = count;

  // Second pass: final labels and areas, each stripe counting into its own histogram.
  auto& areas = buffers_->stripe_areas;
  areas.resize(static_cast<std::size_t>(stripe_count));
#pragma omp parallel for num_threads(team) schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    areas[s].assign(static_cast<std::size_t>(count) + 1, 0);
    std::int32_t* label = result.labels.data() + stripes[s].first * nx;
    const Index points = (stripes[s].last - stripes[s].first) * nx;
    Index* area = areas[s].data();
    for (Index i = 0; i < points; ++i) {
      label[i] = sets.final_label(label[i]);  // the background's label 0 stays 0
      ++area[label[i]];
    }
  }
  result.areas.assign(static_cast<std::size_t>(count), 0);
  for (const auto& stripe_areas : areas)
    for (std::int32_t k = 1; k <= count; ++k)
      result.areas[k - 1] += stripe_areas[k];
  return result;
}

Labelling label_components(const BinaryMap& map, const Topology& topology, int threads) {
  return Labeller(topology, threads).take(map);
}

BinaryMap threshold_above(const HeightMap& heights, Real z) {
  return (heights > z).cast<std::uint8_t>();
}

}  // namespace contactbench
