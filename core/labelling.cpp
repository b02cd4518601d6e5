#include "core/labelling.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "core/large_buffer.hpp"
#include "core/union_find.hpp"

namespace contactbench {

namespace {

// Rows [first, last) of the map, labelled by one thread with provisional labels from [base, ...).
struct Stripe {
  Index first = 0, last = 0;
  std::int32_t base = 0, next = 0;
};

// First pass over one stripe for 4-connectivity: provisional labels, equivalences recorded in `sets`. A point
// looks at its upper and left neighbours only inside the stripe; the stripe's first row is joined to the row
// above it later.
void first_pass_points(const BinaryMap& map, LabelMap& labels, MinRootUnionFind& sets, std::int32_t* area,
                       Stripe& stripe) {
  const Index nx = map.cols();
  std::int32_t next = stripe.base;
  for (Index y = stripe.first; y < stripe.last; ++y) {
    const std::uint8_t* row = map.data() + y * nx;
    const std::uint8_t* up = y > stripe.first ? row - nx : nullptr;
    std::int32_t* label = labels.data() + y * nx;
    const std::int32_t* label_up = up ? label - nx : nullptr;  // no pointer before the array
    // Areas are counted per provisional label, a run of equal labels at a time (one counter bumped point by
    // point would chain every increment through memory).
    std::int32_t run_label = 0, run_length = 0;
    for (Index x = 0; x < nx; ++x) {
      if (!row[x]) {
        label[x] = 0;
        continue;
      }
      const bool left = x > 0 && row[x - 1];
      const bool above = up && up[x];
      if (above && left)
        label[x] = label_up[x] == label[x - 1] ? label[x - 1] : sets.merge(label_up[x], label[x - 1]);
      else if (above)
        label[x] = label_up[x];
      else if (left)
        label[x] = label[x - 1];
      else {
        label[x] = sets.make_set(next++);
        area[label[x]] = 0;
      }
      if (label[x] != run_label) {
        if (run_length > 0) area[run_label] += run_length;  // never touch label 0, shared by the stripes
        run_label = label[x];
        run_length = 0;
      }
      ++run_length;
    }
    if (run_length > 0) area[run_label] += run_length;
  }
  stripe.next = next;
}

// First pass for 8-connectivity over 2 x 2 blocks (the block-based family of Grana, Borghesani and
// Cucchiara 2010): the foreground points of one block always touch each other, so a block is one node of
// the union-find, which makes a quarter of the decisions and merges. With the block's points a b / c d,
// neighbouring blocks are joined when a foreground point of one touches one of the other:
//   up (q): (a|b) and (its c|d);  up-left (p): a and its d;  up-right (r): b and its c;  left (s): (a|c) and
//   (its b|d). Stripes start on even rows, so blocks never straddle two stripes.
void first_pass_blocks(const BinaryMap& map, std::int32_t* block_labels, MinRootUnionFind& sets,
                       std::int32_t* area, Stripe& stripe) {
  const Index nx = map.cols(), blocks = (nx + 1) / 2;
  // Masks (bit 0 a, 1 b, 2 c, 3 d) of the blocks of the block row above and of this one.
  std::vector<std::uint8_t> mask_above(blocks, 0), mask(blocks, 0);
  std::int32_t next = stripe.base;
  for (Index y = stripe.first; y < stripe.last; y += 2) {
    const std::uint8_t* top = map.data() + y * nx;
    const std::uint8_t* bottom = y + 1 < stripe.last ? top + nx : nullptr;
    // One label per block (BBDT's economy: a quarter of the stores of a label per point); the second pass
    // gives it to the block's foreground points.
    std::int32_t* label = block_labels + (y / 2) * blocks;
    const std::int32_t* label_above = y > stripe.first ? label - blocks : nullptr;
    // Areas are summed in a register while consecutive blocks share a label (bumping one counter block
    // after block would chain every addition through memory).
    std::int32_t run_label = 0, run_area = 0;
    for (Index bx = 0; bx < blocks; ++bx) {
      const Index x = 2 * bx;
      // Four background blocks at once (8 bytes of both rows): most of the map at small contact fractions.
      if (x + 8 <= nx && (bx & 3) == 0) {
        std::uint64_t upper, lower = 0;
        std::memcpy(&upper, top + x, 8);
        if (bottom) std::memcpy(&lower, bottom + x, 8);
        if ((upper | lower) == 0) {
          std::memset(mask.data() + bx, 0, 4);
          std::fill(label + bx, label + bx + 4, 0);
          bx += 3;
          continue;
        }
      }
      const bool right = x + 1 < nx;
      const unsigned a = top[x] != 0, b = right && top[x + 1], c = bottom && bottom[x],
                     d = bottom && right && bottom[x + 1];
      const unsigned m = a | b << 1 | c << 2 | d << 3;
      mask[bx] = static_cast<std::uint8_t>(m);
      // Which neighbouring blocks touch this one (see above), computed without branches.
      const unsigned above_left = bx > 0 ? mask_above[bx - 1] : 0, above = mask_above[bx];
      const unsigned above_right = bx + 1 < blocks ? mask_above[bx + 1] : 0, left = bx > 0 ? mask[bx - 1] : 0;
      const bool touches_q = (m & 0b0011) && (above & 0b1100),
                 touches_p = (m & 0b0001) && (above_left & 0b1000);
      const bool touches_r = (m & 0b0010) && (above_right & 0b0100),
                 touches_s = (m & 0b0101) && (left & 0b1010);
      const std::int32_t label_q = touches_q ? label_above[bx] : 0;
      const std::int32_t label_p = touches_p ? label_above[bx - 1] : 0;
      const std::int32_t label_r = touches_r ? label_above[bx + 1] : 0;
      const std::int32_t label_s = touches_s ? label[bx - 1] : 0;
      // The first touching neighbour in the order q, p, r, s gives the label; any other touching neighbour
      // with a different label is merged (rare: most touching neighbours already share their label).
      std::int32_t l = label_s;
      l = label_r ? label_r : l;
      l = label_p ? label_p : l;
      l = label_q ? label_q : l;
      for (const std::int32_t other : {label_p, label_r, label_s})
        if (other && other != l) l = sets.merge(l, other);
      if (m && l == 0) {
        l = sets.make_set(next++);
        area[l] = 0;
      }
      if (l != run_label) {
        if (run_area > 0) area[run_label] += run_area;
        run_label = l;
        run_area = 0;
      }
      run_area += std::popcount(m);
      label[bx] = l;
    }
    if (run_area > 0) area[run_label] += run_area;
    std::swap(mask_above, mask);
  }
  stripe.next = next;
}

// The provisional label of a foreground point: its own (point scan) or its block's (block scan).
class ProvisionalLabel {
 public:
  ProvisionalLabel(const LabelMap& points, const std::int32_t* blocks, Index blocks_per_row)
      : points_(points), blocks_(blocks), blocks_per_row_(blocks_per_row) {}
  std::int32_t operator()(Index y, Index x) const {
    return blocks_ ? blocks_[(y / 2) * blocks_per_row_ + x / 2] : points_(y, x);
  }

 private:
  const LabelMap& points_;
  const std::int32_t* blocks_;
  Index blocks_per_row_;
};

// Joins the points of row y to their neighbours in row y_above, which the first pass did not look at:
// the first row of every stripe, and row 0 to row ny-1 across a periodic seam.
void join_rows(const BinaryMap& map, const ProvisionalLabel& label, MinRootUnionFind& sets,
               const Topology& topology, Index y, Index y_above) {
  const Index nx = map.cols();
  auto join = [&](Index x, Index x_above) {
    if (map(y_above, x_above)) sets.merge(label(y, x), label(y_above, x_above));
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
void join_columns_across_seam(const BinaryMap& map, const ProvisionalLabel& label, MinRootUnionFind& sets,
                              const Topology& topology) {
  const Index nx = map.cols(), ny = map.rows(), last = nx - 1;
  auto join = [&](Index y1, Index x1, Index y2, Index x2) {
    if (map(y1, x1) && map(y2, x2)) sets.merge(label(y1, x1), label(y2, x2));
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

// Second pass of the block scan: each foreground point takes its block's final label (looked up once per
// block, and given without a branch through a mask; any non-zero value of the map is foreground).
void expand_blocks(const BinaryMap& map, const std::int32_t* block_labels, const MinRootUnionFind& sets,
                   LabelMap& labels, Index first_row, Index last_row) {
  const Index nx = map.cols(), blocks = (nx + 1) / 2, pairs = nx / 2;
  for (Index y = first_row; y < last_row; y += 2) {
    const std::int32_t* block = block_labels + (y / 2) * blocks;
    const Index rows = std::min<Index>(2, last_row - y);
    for (Index r = 0; r < rows; ++r) {
      const std::uint8_t* in = map.data() + (y + r) * nx;
      std::int32_t* out = labels.data() + (y + r) * nx;
      for (Index bx = 0; bx < pairs; ++bx) {
        const std::int32_t label = sets.final_label(block[bx]);
        out[2 * bx] = label & -static_cast<std::int32_t>(in[2 * bx] != 0);
        out[2 * bx + 1] = label & -static_cast<std::int32_t>(in[2 * bx + 1] != 0);
      }
      if (nx % 2) out[nx - 1] = sets.final_label(block[pairs]) & -static_cast<std::int32_t>(in[nx - 1] != 0);
    }
  }
}

}  // namespace

struct Labeller::Buffers {
  Labelling result;
  MinRootUnionFind sets;
  LargeBuffer<std::int32_t> provisional_area;
  LargeBuffer<std::int32_t> block_labels;  // block scan (8-connectivity) only
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

  // Stripes start on even rows (2 x 2 blocks never straddle two stripes); empty ones are dropped.
  std::vector<Stripe> stripes;
  for (Index s = 0, requested = std::clamp<Index>(threads_, 1, ny); s < requested; ++s) {
    const Index first = (s * ny / requested) & ~Index{1},
                last = s + 1 == requested ? ny : ((s + 1) * ny / requested) & ~Index{1};
    if (first < last)
      stripes.push_back({first, last, static_cast<std::int32_t>(1 + first * labels_per_row), 0});
  }
  const Index stripe_count = static_cast<Index>(stripes.size());
  sets.reset(static_cast<std::size_t>(1 + ny * labels_per_row));
  // Points per provisional label, counted in the first pass.
  buffers_->provisional_area.resize(static_cast<std::size_t>(1 + ny * labels_per_row));
  std::int32_t* area = buffers_->provisional_area.data();
  const bool by_block = topology_.connectivity == Connectivity::eight;
  const Index blocks_per_row = (nx + 1) / 2;
  if (by_block) buffers_->block_labels.resize(static_cast<std::size_t>((ny + 1) / 2 * blocks_per_row));
  std::int32_t* block_labels = by_block ? buffers_->block_labels.data() : nullptr;
  const ProvisionalLabel provisional(result.labels, block_labels, blocks_per_row);

  // Stripes follow the thread count (so the result and the seams are the same for any size); only maps
  // large enough to pay for a parallel region get one.
  const int team = nx * ny >= kMinPointsForThreads ? static_cast<int>(stripe_count) : 1;
#pragma omp parallel for num_threads(team) schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    if (topology_.connectivity == Connectivity::four)
      first_pass_points(map, result.labels, sets, area, stripes[s]);
    else
      first_pass_blocks(map, block_labels, sets, area, stripes[s]);
  }

  // Seams between stripes and periodic seams: a few rows and two columns, done by one thread.
  for (Index s = 1; s < stripe_count; ++s)
    join_rows(map, provisional, sets, topology_, stripes[s].first, stripes[s].first - 1);
  if (topology_.wrap_y) join_rows(map, provisional, sets, topology_, 0, ny - 1);
  if (topology_.wrap_x) join_columns_across_seam(map, provisional, sets, topology_);

  std::int32_t count = 0;
  for (const Stripe& stripe : stripes)
    sets.flatten(stripe.base, stripe.next, count);
  result.count = count;

  result.areas.assign(static_cast<std::size_t>(count), 0);
  for (const Stripe& stripe : stripes)
    for (std::int32_t l = stripe.base; l < stripe.next; ++l)
      result.areas[sets.final_label(l) - 1] += area[l];

      // Second pass: final labels; for the point scan a gather with no branch (the background's 0 stays 0).
#pragma omp parallel for num_threads(team) schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    if (by_block) {
      expand_blocks(map, block_labels, sets, result.labels, stripes[s].first, stripes[s].last);
      continue;
    }
    std::int32_t* label = result.labels.data() + stripes[s].first * nx;
    const Index points = (stripes[s].last - stripes[s].first) * nx;
    for (Index i = 0; i < points; ++i)
      label[i] = sets.final_label(label[i]);
  }
  return result;
}

Labelling label_components(const BinaryMap& map, const Topology& topology, int threads) {
  return Labeller(topology, threads).take(map);
}

BinaryMap threshold_above(const HeightMap& heights, Real z) {
  return (heights > z).cast<std::uint8_t>();
}

}  // namespace contactbench
