#include "contactbench/core/labelling.hpp"

#include <algorithm>
#include <bit>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/large_buffer.hpp"
#include "contactbench/core/union_find.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace contactbench {

namespace labelling_detail {

// A run of a band: columns [start, end) hold foreground in at least one of the band's rows, the columns on
// either side hold none. Its provisional label covers every foreground point of the band in those columns.
struct Run {
  std::int32_t start, end, label;
};

// The runs of one band: [begin, end) in the run buffer, in increasing order of columns.
struct Band {
  Index begin = 0, end = 0;
};

}  // namespace labelling_detail

using labelling_detail::Band;
using labelling_detail::Run;

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
      // [[likely]] keeps the background in a tight loop of its own (the compiler's layout of this loop
      // otherwise depends on the other code inlined beside it).
      if (!row[x]) [[likely]] {
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

// 8-connectivity by runs of two-row bands, on rows packed into bits: the bit-merge-run scan (BMRS) of Lee,
// Bolelli, Allegretti and Grana, "Fast Run-Based Connected Components Labeling for Bitonal Images" (IVPR
// 2021; YACCLAB's labeling_lee_2021_bmrs.h), written here for byte maps, stripes and areas. Rows y and y+1
// (y even) form a band; OR-ing them gives one row whose runs of foreground columns are exactly the band's
// connected pieces, since with 8-connectivity every foreground point of a column touches every one of the
// next column within the band. So a run is one node of the union-find (the economy of the 2 x 2 blocks of
// BBDT, Grana, Borghesani and Cucchiara 2010, taken to a whole run), and the decisions are made 64 columns
// at a time on bits, then once per run, never once per point or block.

using Bits = std::uint64_t;
constexpr Index kWordBits = 64;

// The number of set bits in a and b (std::popcount is a library call unless the target has POPCNT; the
// fallback counts both words in one SWAR sum).
inline Index count_bits(Bits a, Bits b) {
#if defined(__POPCNT__)
  return std::popcount(a) + std::popcount(b);
#else
  constexpr Bits k1 = 0x5555555555555555ULL, k2 = 0x3333333333333333ULL, k4 = 0x0f0f0f0f0f0f0f0fULL;
  a -= (a >> 1) & k1;
  b -= (b >> 1) & k1;
  Bits sum = (a & k2) + ((a >> 2) & k2) + (b & k2) + ((b >> 2) & k2);  // 4-bit fields up to 8
  sum = (sum & k4) + ((sum >> 4) & k4);                                // bytes up to 16
  return static_cast<Index>((sum * 0x0101010101010101ULL) >> 56);
#endif
}

// One row of the map as bits: bit x % 64 of word x / 64 is set when point x is foreground (any non-zero
// value); the bits past the row's end are 0.
void pack_row(const std::uint8_t* row, Index nx, Bits* bits) {
  Index x = 0;
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  for (; x + kWordBits <= nx; x += kWordBits) {
    Bits word = 0;
    for (int k = 0; k < 4; ++k) {
      const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + x + 16 * k));
      const auto background = static_cast<unsigned>(_mm_movemask_epi8(_mm_cmpeq_epi8(bytes, zero)));
      word |= static_cast<Bits>(~background & 0xffffu) << (16 * k);
    }
    bits[x / kWordBits] = word;
  }
#endif
  for (; x < nx; x += kWordBits) {
    Bits word = 0;
    for (Index i = 0, n = std::min(kWordBits, nx - x); i < n; ++i)
      word |= static_cast<Bits>(row[x + i] != 0) << i;
    bits[x / kWordBits] = word;
  }
}

// Whether any bit in [lo, hi] (inclusive) is set.
inline bool any_bit(const Bits* bits, Index lo, Index hi) {
  const Index first = lo / kWordBits, last = hi / kWordBits;
  const Bits from_lo = ~Bits{0} << (lo % kWordBits), to_hi = ~Bits{0} >> (kWordBits - 1 - hi % kWordBits);
  if (first == last) return (bits[first] & from_lo & to_hi) != 0;
  if (bits[first] & from_lo) return true;
  for (Index w = first + 1; w < last; ++w)
    if (bits[w]) return true;
  return (bits[last] & to_hi) != 0;
}

// The set bits of a and b in columns [start, end), end > start.
inline Index count_bits(const Bits* a, const Bits* b, Index start, Index end) {
  const Index first = start / kWordBits, last = (end - 1) / kWordBits;
  const Bits from_start = ~Bits{0} << (start % kWordBits),
             to_end = ~Bits{0} >> (kWordBits - 1 - (end - 1) % kWordBits);
  if (first == last) return count_bits(a[first] & from_start & to_end, b[first] & from_start & to_end);
  Index count = count_bits(a[first] & from_start, b[first] & from_start) +
                count_bits(a[last] & to_end, b[last] & to_end);
  for (Index w = first + 1; w < last; ++w)
    count += count_bits(a[w], b[w]);
  return count;
}

// First pass over one stripe for 8-connectivity: the runs of its bands (from runs + first_run on), their
// provisional labels (a new one for a run that touches no run of the band above, in raster order of the
// runs, which is the raster order of their first 2 x 2 blocks), the equivalences in `sets`, the points per
// provisional label in `area`. Stripes start on even rows, so bands never straddle two stripes; the
// stripe's first band is joined to the band above it later.
void first_pass_runs(const BinaryMap& map, Run* runs, Band* bands, MinRootUnionFind& sets, std::int32_t* area,
                     Stripe& stripe, Index first_run) {
  const Index nx = map.cols(), words = (nx + kWordBits - 1) / kWordBits;
  // The band's two rows, the bottom row of the band above, and where that row touches the top row.
  std::vector<Bits> top(words), bottom(words), above(words), contact(words);
  std::int32_t next = stripe.base;
  Index out = first_run;
  const Band* band_above = nullptr;
  for (Index y = stripe.first; y < stripe.last; y += 2) {
    pack_row(map.data() + y * nx, nx, top.data());
    if (y + 1 < stripe.last)
      pack_row(map.data() + (y + 1) * nx, nx, bottom.data());
    else
      std::fill(bottom.begin(), bottom.end(), 0);
    // Bit x of `contact` (BMRS's junction flags): foreground in columns {x-1, x} of both the row above and
    // the top row; any two such points touch. A run and a run of the band above are joined when a contact
    // bit lies where their columns meet (or where one stops a column short of the other).
    if (band_above) {
      Bits carry_above = 0, carry_top = 0;
      for (Index w = 0; w < words; ++w) {
        const Bits a = above[w], t = top[w];
        contact[w] = (a | a << 1 | carry_above) & (t | t << 1 | carry_top);
        carry_above = a >> (kWordBits - 1);
        carry_top = t >> (kWordBits - 1);
      }
    }
    const Run* up = band_above ? runs + band_above->begin : nullptr;
    const Run* const up_end = band_above ? runs + band_above->end : nullptr;
    // A run [start, end) of this band: its label, from the runs of the band above that it touches (merged
    // when they differ) or a new one, and its points.
    auto close_run = [&](Index start, Index end) {
      std::int32_t label = 0;
      if (up) {
        // Runs above that end two columns or more before this run's first touch neither it nor the runs
        // after it.
        while (up != up_end && up->end < start)
          ++up;
        for (const Run* u = up; u != up_end && u->start <= end; ++u) {
          // Contact bits x in [lo, hi] involve columns x-1 and x: points of the two runs, or background (the
          // column before a run and the one at its end are background). Bit end (or u->end) covers a run
          // that stops a column short of the other; bit nx would repeat bit nx - 1.
          const Index lo = std::max<Index>(start, u->start), hi = std::min<Index>({end, u->end, nx - 1});
          if (!any_bit(contact.data(), lo, hi)) continue;
          if (label == 0)
            label = u->label;
          else if (label != u->label)
            label = sets.merge(label, u->label);
        }
      }
      if (label == 0) {
        label = sets.make_set(next++);
        area[label] = 0;
      }
      area[label] += static_cast<std::int32_t>(count_bits(top.data(), bottom.data(), start, end));
      runs[out++] = {static_cast<std::int32_t>(start), static_cast<std::int32_t>(end), label};
    };
    // The runs are where the merged row (top | bottom) changes, found a word of 64 columns at a time.
    bands[y / 2].begin = out;
    bool open = false;
    Index start = 0;
    Bits carry = 0;
    for (Index w = 0; w < words; ++w) {
      const Bits merged = top[w] | bottom[w];
      if ((merged | carry) == 0) continue;  // background, with no run open: most of a sparse map
      Bits changes = merged ^ (merged << 1 | carry);
      carry = merged >> (kWordBits - 1);
      for (; changes; changes &= changes - 1) {
        const Index x = w * kWordBits + std::countr_zero(changes);
        if (open)
          close_run(start, x);
        else
          start = x;
        open = !open;
      }
    }
    if (open) close_run(start, nx);
    bands[y / 2].end = out;
    band_above = &bands[y / 2];
    std::swap(above, bottom);
  }
  stripe.next = next;
}

// The provisional label of a foreground point: its own (point scan) or its run's (run scan).
class ProvisionalLabel {
 public:
  ProvisionalLabel(const LabelMap& points, const Run* runs, const Band* bands)
      : points_(points), runs_(runs), bands_(bands) {}
  std::int32_t operator()(Index y, Index x) const {
    if (!runs_) return points_(y, x);
    // The last run of the band starting at or before x, which holds x since (y, x) is foreground.
    const Band& band = bands_[y / 2];
    const Run* run = std::upper_bound(runs_ + band.begin, runs_ + band.end, x,
                                      [](Index column, const Run& r) { return column < r.start; });
    return (run - 1)->label;
  }

 private:
  const LabelMap& points_;
  const Run* runs_;
  const Band* bands_;
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

// Second pass of the run scan, row by row: each foreground point takes its run's final label (looked up once
// per run, and given without a branch, a loop the compiler vectorises; any non-zero value of the map is
// foreground), the gaps between runs 0 (a fill: faster than the same loop, which must read the map).
void expand_runs(const BinaryMap& map, const Run* runs, const Band* bands, const MinRootUnionFind& sets,
                 LabelMap& labels, Index first_row, Index last_row) {
  const Index nx = map.cols();
  for (Index y = first_row; y < last_row; ++y) {
    const std::uint8_t* in = map.data() + y * nx;
    std::int32_t* out = labels.data() + y * nx;
    Index x = 0;
    for (Index r = bands[y / 2].begin; r < bands[y / 2].end; ++r) {
      const Index start = runs[r].start, end = runs[r].end;
      std::fill(out + x, out + start, 0);
      const std::int32_t label = sets.final_label(runs[r].label);
      for (x = start; x < end; ++x)
        out[x] = in[x] != 0 ? label : 0;
    }
    std::fill(out + x, out + nx, 0);
  }
}

}  // namespace

struct Labeller::Buffers {
  Labelling result;
  MinRootUnionFind sets;
  LargeBuffer<std::int32_t> provisional_area;
  LargeBuffer<Run> runs;    // run scan (8-connectivity) only
  std::vector<Band> bands;  // the same
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

  // Stripes start on even rows (bands of two rows never straddle two stripes); empty ones are dropped.
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
  // Runs for 8-connectivity: a band holds at most ceil(nx/2) runs (a run ends with a background column), and
  // each stripe writes its bands' runs one after the other from where its first band's runs may start.
  const bool by_runs = topology_.connectivity == Connectivity::eight;
  if (by_runs) {
    buffers_->runs.resize(static_cast<std::size_t>((ny + 1) / 2 * labels_per_row));
    buffers_->bands.resize(static_cast<std::size_t>((ny + 1) / 2));
  }
  Run* runs = by_runs ? buffers_->runs.data() : nullptr;
  Band* bands = by_runs ? buffers_->bands.data() : nullptr;
  const ProvisionalLabel provisional(result.labels, runs, bands);

  // Stripes follow the thread count (so the result and the seams are the same for any size); only maps
  // large enough to pay for a parallel region get one.
  const int team = team_size(nx * ny, static_cast<int>(stripe_count));
#pragma omp parallel for num_threads(team) schedule(static, 1)
  for (Index s = 0; s < stripe_count; ++s) {
    if (topology_.connectivity == Connectivity::four)
      first_pass_points(map, result.labels, sets, area, stripes[s]);
    else
      first_pass_runs(map, runs, bands, sets, area, stripes[s], stripes[s].first / 2 * labels_per_row);
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
    if (by_runs) {
      expand_runs(map, runs, bands, sets, result.labels, stripes[s].first, stripes[s].last);
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
