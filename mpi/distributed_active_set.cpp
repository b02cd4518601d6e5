#include "contactbench/mpi/distributed_active_set.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "contactbench/bem/box_sum.hpp"
#include "contactbench/bem/solvers/active_set_method.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/mpi/distributed_restriction.hpp"
#include "contactbench/mpi/distributed_selection.hpp"

namespace contactbench::mpi {

using namespace active_set_tuning;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The serial interpolate_up's arithmetic (bem/solvers/active_set_coarse_start.cpp), for one fine row from
// the two coarse rows it reads: along x first (0.75 of the nearer coarse pixel, 0.25 of the other, rounded
// to the field's type), then along y, clamped to [0, cap].
Index neighbour(Index i, Index step, Index n, bool periodic) {
  const Index j = i + step;
  if (periodic) return (j + n) % n;
  return std::clamp<Index>(j, 0, n - 1);
}

void interpolate_along_x(const double* coarse_row, Index cnx, bool periodic, double* fine_row) {
  for (Index x = 0; x < 2 * cnx; ++x) {
    const Index c = x / 2, other = neighbour(c, x % 2 == 0 ? -1 : 1, cnx, periodic);
    fine_row[x] = 0.75 * coarse_row[c] + 0.25 * coarse_row[other];
  }
}

}  // namespace

// The next coarser level: on slabs (a DistributedActiveSet of the restricted heights) or gathered to every
// rank and solved by the serial method, identical on each.
class DistributedActiveSet::Coarse {
 public:
  Coarse(const Grid& fine, const std::vector<double>& fine_heights, Real modulus, MPI_Comm comm, int threads,
         Index gather_bound)
      : grid_(fine) {
    grid_.nx = fine.nx / 2;
    grid_.ny = fine.ny / 2;
    layout_ = all_slabs(grid_.nx, grid_.ny, comm);
    slab_ = layout_[static_cast<std::size_t>(rank_of(comm))];
    std::vector<double> heights;
    {  // the fine slab's copy freed before the level is made
      const Slab fine_slab = slab_of(fine, comm);
      HeightMap local(fine_slab.count, fine.nx);
      std::copy(fine_heights.begin(), fine_heights.end(), local.data());
      const HeightMap restricted = restrict_to_coarse_slab(fine, local, comm);
      heights.assign(restricted.data(), restricted.data() + restricted.size());
    }
    if (grid_.points() > gather_bound) {
      distributed_ = std::make_unique<DistributedActiveSet>(grid_, std::move(heights), modulus, comm, threads,
                                                            gather_bound);
    } else {
      // Every rank the whole level (rank order is row order), solved as the serial method's own coarse
      // level is made (ActiveSet::make_coarse_level: estimated plans).
      std::vector<int> counts, offsets;
      for (const Slab& s : layout_) {
        counts.push_back(static_cast<int>(s.points()));
        offsets.push_back(static_cast<int>(s.start * s.nx));
      }
      std::vector<double> whole(static_cast<std::size_t>(grid_.points()));
      MPI_Allgatherv(heights.data(), static_cast<int>(heights.size()), MPI_DOUBLE, whole.data(),
                     counts.data(), offsets.data(), MPI_DOUBLE, comm);
      serial_ =
          std::make_unique<ActiveSet<double>>(grid_, std::move(whole), modulus, threads, FftRigor::estimate);
    }
    // The coarse rows each rank's fine rows read: c = y / 2 and its neighbour above or below.
    const std::vector<Slab> fine_layout = all_slabs(fine.nx, fine.ny, comm);
    auto needs = [&](int r) {
      const Slab& s = fine_layout[static_cast<std::size_t>(r)];
      std::vector<Index> rows;
      for (Index y = s.start; y < s.start + s.count; ++y) {
        rows.push_back(y / 2);
        rows.push_back(neighbour(y / 2, y % 2 == 0 ? -1 : 1, grid_.ny, grid_.periodic));
      }
      return rows;
    };
    if (distributed_) rows_ = std::make_unique<RowExchange>(layout_, rank_of(comm), needs, comm);
  }

  // Solves the level; writes the interpolated pressure on the fine slab `fine`; the level's contact fraction.
  ActiveSetOutcome solve(const ActiveSetProblem& problem, const Slab& fine, double cap,
                         std::vector<double>& p, double& contact_fraction,
                         const std::function<void()>& between) {
    std::vector<double> pressure;
    ActiveSetOutcome outcome;
    if (distributed_) {
      outcome = distributed_->solve(problem, kCoarseTolerance, 100000, false, pressure, between);
      contact_fraction = distributed_->contact_fraction();
      rows_->exchange(pressure.data());
    } else {
      outcome = serial_->solve(problem, kCoarseTolerance, 100000, false, pressure, between);
      // The serial level's fraction in contact, p > 0 (elastic or plastic at the hardness).
      const auto touching = std::count_if(pressure.begin(), pressure.end(), [](double v) { return v > 0; });
      contact_fraction = static_cast<double>(touching) / static_cast<double>(grid_.points());
    }
    auto coarse_row = [&](Index c) { return distributed_ ? rows_->row(c) : pressure.data() + c * grid_.nx; };
    const Index cnx = grid_.nx, nx = 2 * cnx;
    std::vector<double> near(static_cast<std::size_t>(nx)), far(static_cast<std::size_t>(nx));
    p.resize(static_cast<std::size_t>(fine.points()));
    for (Index r = 0; r < fine.count; ++r) {
      const Index y = fine.start + r;
      const Index c = y / 2, other = neighbour(c, y % 2 == 0 ? -1 : 1, grid_.ny, grid_.periodic);
      interpolate_along_x(coarse_row(c), cnx, grid_.periodic, near.data());
      interpolate_along_x(coarse_row(other), cnx, grid_.periodic, far.data());
      for (Index x = 0; x < nx; ++x)
        p[static_cast<std::size_t>(r * nx + x)] = std::clamp(0.75 * near[x] + 0.25 * far[x], 0.0, cap);
    }
    return outcome;
  }

  std::size_t bytes() const {
    // Gathered: the serial level's ~56 B a point (ActiveSet's fields) and its own coarser levels (a third
    // more), about 12 doubles a point of this level, on every rank. On slabs: the level's own peak, and the
    // pressure it returns (8 B a point of its slab).
    return distributed_ ? distributed_->bytes() + sizeof(double) * static_cast<std::size_t>(slab_.points())
                        : sizeof(double) * 12 * static_cast<std::size_t>(grid_.points());
  }

 private:
  Grid grid_;
  std::vector<Slab> layout_;
  Slab slab_;
  std::unique_ptr<DistributedActiveSet> distributed_;
  std::unique_ptr<ActiveSet<double>> serial_;
  std::unique_ptr<RowExchange> rows_;
};

void DistributedActiveSet::Sums::add(const Sums& o) {
  a += o.a;
  b += o.b;
  c += o.c;
  d += o.d;
  g += o.g;
  h += o.h;
  e = std::max(e, o.e);
  f = std::max(f, o.f);
}

DistributedActiveSet::DistributedActiveSet(const Grid& grid, std::vector<double> local_heights, Real modulus,
                                           MPI_Comm comm, int threads, Index gather_bound)
    : grid_(grid),
      comm_(comm),
      slab_(slab_of(grid, comm)),
      layout_(all_slabs(grid.nx, grid.ny, comm)),
      modulus_(modulus),
      threads_(threads),
      gather_bound_(gather_bound),
      operator_(grid, modulus, comm, threads),
      // The filter runs between the operator's applications, never during one: one transform for both.
      // On the slab engine (two ranks and more, one thread a rank) in float, as the serial filter: the
      // same FFTW plans of the same lengths and batches, so the same values (bit for bit in
      // DistributedFilter's cases; docs/mpi.md "Exchanges in shared memory"). Elsewhere in double, its input
      // and output rounded to float as the serial filter rounds them (filter_pass).
      filter_(make_distributed_unit_preconditioner(grid, comm, threads, &operator_.convolution(), true)),
      n_(static_cast<std::size_t>(slab_.points())),
      points_(static_cast<double>(grid.points())),
      h_(std::move(local_heights)) {
  throw_on_any_rank(h_.size() != n_,
                    "distributed active_set: the local heights have " + std::to_string(h_.size()) +
                        " values, this rank's slab " + std::to_string(n_),
                    comm);
  u_.assign(n_, 0.0);  // the work arrays are made by each solve (make_work)
  changes_.reserve(kFewChanges);
  measure_heights();
  if (extension_radius() > 0) {
    halo_ = std::make_unique<RowExchange>(
        RowExchange::halo(layout_, rank_of(comm), extension_radius(), grid.periodic, comm));
    window_ = WindowRows(grid.nx, grid.ny, extension_radius(), grid.periodic);
  }
  const Index nx = grid.nx, ny = grid.ny;
  has_coarse_ = nx % 2 == 0 && ny % 2 == 0 && nx / 2 >= kCoarsest && ny / 2 >= kCoarsest;
}

DistributedActiveSet::~DistributedActiveSet() = default;

std::size_t DistributedActiveSet::bytes() const {
  // Held from solve to solve: h and u (16 B a point of the slab), the operator's transform (which the filter
  // shares) and both multipliers. During a solve, first the coarse level (made for the cold start, freed
  // when it has given its pressure: its own peak, recorded when it ran), then this level's work arrays.
  return kept_bytes() + std::max(work_bytes(), coarse_peak_);
}

std::size_t DistributedActiveSet::kept_bytes() const {
  return 2 * sizeof(double) * n_ + operator_.bytes() + filter_->own_bytes();
}

// r, z, t; the weights (float), the window counts (16 bits) and the two sets (8 bits each): 32 B a point.
std::size_t DistributedActiveSet::work_bytes() const {
  return (3 * sizeof(double) + sizeof(float) + sizeof(std::uint16_t) + 2) * n_;
}

// The work arrays, made after the coarse start (which then no longer holds its own) and freed when a solve
// ends (docs/mpi.md "Memory a point"). Every value read is written first within a solve (the direction t
// only as 0 * t when beta = 0, so zeros are as good as the last solve's values).
void DistributedActiveSet::make_work() {
  for (auto* field : {&r_, &z_, &t_})
    field->assign(n_, 0.0);
  extension_weight_.assign(n_, 0.0f);
  window_count_.assign(n_, 0);
  in_.assign(n_, 0);
  plastic_.assign(n_, 0);
}

void DistributedActiveSet::free_work() {
  for (auto* field : {&r_, &z_, &t_})
    std::vector<double>().swap(*field);
  std::vector<float>().swap(extension_weight_);
  std::vector<std::uint16_t>().swap(window_count_);
  std::vector<std::uint8_t>().swap(in_);
  std::vector<std::uint8_t>().swap(plastic_);
}

double DistributedActiveSet::threshold(double tolerance, double d) const {
  return std::max(tolerance * (highest_ - d), gap_round_off_);
}

Index DistributedActiveSet::extension_radius() const {
  return std::min(kExtensionRadius, (std::min(grid_.nx, grid_.ny) - 1) / 2);
}

DistributedActiveSet::Sums DistributedActiveSet::reduced(const Sums& mine) const {
  const int ranks = size_of(comm_);
  const double values[8] = {mine.a, mine.b, mine.c, mine.d, mine.g, mine.h, mine.e, mine.f};
  const std::vector<double>& all = gathered(values, 8);
  Sums total;
  total.e = total.f = -kInfinity;
  for (int r = 0; r < ranks; ++r) {
    const double* v = all.data() + 8 * r;
    total.add(Sums{.a = v[0], .b = v[1], .c = v[2], .d = v[3], .g = v[4], .h = v[5], .e = v[6], .f = v[7]});
  }
  return total;
}

template <class Body>
DistributedActiveSet::Sums DistributedActiveSet::over_points(Body body) {
  Sums local;
  body(std::size_t{0}, n_, local);
  return reduced(local);
}

template <class Input, class Output>
DistributedActiveSet::Sums DistributedActiveSet::fresh_displacement(std::vector<double>& p, Input on_input,
                                                                    Output on_output) {
  // p's rescaling on its way into the transform, u and the sums on their way out (the serial count_on_set).
  const Index nx = grid_.nx;
  Sums part;
  operator_.apply(
      [&](Index r, double* row) {
        for (Index x = 0; x < nx; ++x) {
          const std::size_t k = static_cast<std::size_t>(r * nx + x);
          on_input(k);
          row[x] = p[k];
        }
      },
      [&](Index r, const double* row) {
        for (Index x = 0; x < nx; ++x) {
          const std::size_t k = static_cast<std::size_t>(r * nx + x);
          u_[k] = row[x];
          on_output(k, part);
        }
      });
  displacement_current_ = displacement_fresh_ = true;
  return reduced(part);
}

bool DistributedActiveSet::load_scale(double elastic, double plastic, double total, double& factor) {
  const double elastic_total = total - plastic;
  if (plastic > 0 && !(elastic_total > 0)) return false;
  factor = elastic > 0 ? elastic_total / elastic : 0;
  return true;
}

void DistributedActiveSet::add_residual(Sums& part, double x) {
  part.a += x;
  part.b += x * x;
  part.e = std::max(part.e, x);
  part.f = std::max(part.f, -x);
}

double DistributedActiveSet::start_score(const std::vector<double>& p, std::size_t k, double d,
                                         double stiffness) const {
  const double g = d + u_[k] - h_[k];
  return p[k] - stiffness * g;
}

void DistributedActiveSet::measure_heights() {
  double low = kInfinity, high = -kInfinity;
  for (const double v : h_) {
    low = std::min(low, v);
    high = std::max(high, v);
  }
  double extremes[2] = {-low, high};
  MPI_Allreduce(MPI_IN_PLACE, extremes, 2, MPI_DOUBLE, MPI_MAX, comm_);
  low = -extremes[0];
  highest_ = extremes[1];
  gap_round_off_ = 8 * std::numeric_limits<double>::epsilon() * std::max(std::abs(low), std::abs(highest_));
  height_range_ = highest_ - low;
  if (!(height_range_ > 0)) height_range_ = 1;
}

ActiveSetOutcome DistributedActiveSet::solve(const ActiveSetProblem& problem, double tolerance,
                                             Index max_iterations, bool warm, std::vector<double>& p,
                                             const std::function<void()>& between) {
  ActiveSetOutcome outcome;
  load_control_ = problem.load_control;
  separation_ = problem.separation;
  cap_ = std::isfinite(problem.hardness) ? problem.hardness : kInfinity;
  const double total = problem.mean_pressure * points_;
  displacement_current_ = displacement_fresh_ = false;
  throw_on_any_rank(warm && p.size() != n_,
                    "distributed active_set: a warm start of " + std::to_string(p.size()) +
                        " values for a slab of " + std::to_string(n_),
                    comm_);
  if (!warm) {
    const ActiveSetOutcome coarse = nested_start(problem, p, between);
    outcome.coarse_iterations = coarse.iterations;
    outcome.work = coarse.work / 4;
  }
  make_work();
  double d = 0;
  Sums kept = start_sets(p, warm, total, d);
  bool capping = warm;
  bool final = false;
  Index inner = 0, fresh = 0, column_updates = 0;
  for (Index outer = 1; outer <= kMaxOuter; ++outer) {
    if (kept.c > 0) {
      if (displacement_current_ && kept.c <= kFewChanges) {
        add_columns(static_cast<Index>(kept.c));
        ++column_updates;
      } else {
        displacement_current_ = displacement_fresh_ = false;
      }
    }
    double scale = 1;
    if (load_control_) {
      const bool unloaded = !(kept.a > 0);
      if (unloaded) {
        for (std::size_t k = 0; k < n_; ++k)
          if (in_[k]) p[k] = 1;
        displacement_current_ = displacement_fresh_ = false;
      }
      const bool scalable =
          kept.b > 0 && (unloaded ? scale_to(p, total) : load_scale(kept.a, kept.g, total, scale));
      if (!scalable) {
        reseat(p, total);
        scale_to(p, total);
        scale = 1;
      } else if (rescales_the_load(scale) && kept.g > 0) {  // as the serial method chooses
        displacement_current_ = displacement_fresh_ = false;
      }
    }
    fresh += displacement_current_ ? 0 : 1;
    const Index steps = cg_on_set(p, scale, final ? 0.0 : kInnerReduction, threshold(tolerance, d),
                                  final ? tolerance : 0.0, max_iterations - inner - fresh, between);
    inner += steps;
    d = load_control_ ? -set_mean_ : separation_;
    const double limit = threshold(tolerance, d);
    const double entry = outer <= kLaxEntrySteps ? gap_round_off_ : limit;
    const Sums update = update_sets(p, d, limit, entry, capping);
    const double residual = update.e;
    const Index changed = static_cast<Index>(update.h);
    kept = update;
    outcome.outer = outer;
    outcome.residual = residual / height_range_;
    outcome.change = last_step_change_;
    outcome.iterations = inner + fresh + 1;
    const bool above_cap = update.d > 0;
    if (converged(changed, above_cap, residual, limit, tolerance)) {
      outcome.converged = true;
      break;
    }
    if (changed == 0 && above_cap && !capping) {
      capping = true;
      final = false;
      continue;
    }
    if (changed == 0 && final && steps == 0) break;
    final = changed == 0;
    if (outcome.iterations >= max_iterations) break;
  }
  finish(p, total, tolerance, d, kept, inner + column_updates, outcome);
  free_work();
  outcome.work += static_cast<double>(outcome.iterations);
  outcome.iterations = std::llround(outcome.work);
  return outcome;
}

void DistributedActiveSet::finish(std::vector<double>& p, double total, double tolerance, double d,
                                  const Sums& kept, Index steps, ActiveSetOutcome& outcome) {
  const Sums held = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k)
      if (in_[k]) {
        const double clamped = std::clamp(p[k], 0.0, cap_);
        part.c += clamped != p[k] ? 1.0 : 0.0;
        p[k] = clamped;
      }
  });
  const bool clipped = kept.c > 0 || held.c > 0;
  if (clipped && load_control_) scale_to(p, total);
  const double drift =
      static_cast<double>(steps + 1) * std::numeric_limits<double>::epsilon() * height_range_;
  const bool drifted = !displacement_fresh_ && kDriftMargin * drift > threshold(tolerance, d);
  if (clipped || !displacement_current_ || drifted) {
    operator_.apply(p.data(), u_.data());
    displacement_current_ = displacement_fresh_ = true;
    ++outcome.iterations;
  }
  const Sums last = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k) {
      in_[k] = p[k] > 0 && !plastic_[k];
      part.d += in_[k] || plastic_[k] ? 1.0 : 0.0;
      part.g += p[k];
      if (in_[k]) {
        part.a += u_[k] - h_[k];
        part.b += 1;
      }
    }
  });
  outcome.separation = load_control_ ? flat_height(last) : separation_;
  outcome.pressure_sum = last.g;
  contact_fraction_ = last.d / points_;
}

void DistributedActiveSet::displacement_minus_heights(std::vector<double>& out) const {
  out.resize(n_);
  for (std::size_t k = 0; k < n_; ++k)
    out[k] = u_[k] - h_[k];
}

// The sets (bem/solvers/active_set_sets.cpp).

void DistributedActiveSet::reseat(std::vector<double>& p, double total) {
  const double most = std::isfinite(cap_) ? std::ceil(total / cap_) - 1 : 0.0;
  const std::size_t m = static_cast<std::size_t>(std::clamp(most, 0.0, points_ - 1));
  operator_.apply(p.data(), u_.data());
  std::vector<double> depths(n_);
  for (std::size_t k = 0; k < n_; ++k)
    depths[k] = h_[k] - u_[k];
  const double level = kth_largest_over_ranks(depths, m + 1, comm_);  // nth_element's m-th, from 0
  for (std::size_t k = 0; k < n_; ++k) {
    const double depth = h_[k] - u_[k];
    plastic_[k] = depth > level;
    in_[k] = depth == level;
    p[k] = plastic_[k] ? cap_ : (in_[k] ? 1.0 : 0.0);
  }
  displacement_current_ = displacement_fresh_ = false;
}

void DistributedActiveSet::keep_to_sets(std::vector<double>& p, std::size_t k, Sums& part) {
  const double before = p[k];
  const double held = plastic_[k] ? cap_ : (in_[k] ? before : 0.0);
  if (held != before) {
    p[k] = held;
    part.c += 1;
    if (part.c <= kFewChanges)
      changes_.push_back(
          {static_cast<double>(slab_.start * grid_.nx + static_cast<Index>(k)), held - before});
  }
  part.a += in_[k] ? held : 0.0;
  part.b += in_[k];
  part.g += plastic_[k] ? cap_ : 0.0;
}

// u += G dp for the `changed` changes of p the last keep_to_sets pass made (at most kFewChanges over all
// ranks, each rank's own in changes_, in node order): the operator applied to the changes alone. The serial
// method adds dp times G's column of each node from its response to a unit load at node 0 (G e_0, a field of
// the whole grid); on slabs that field would be 8 B a point of the grid on every rank, whatever the number of
// ranks (docs/mpi.md "Memory a point"), so the transform makes the same sum (to round-off) from no stored
// field, at the cost of one transform pair when few pressures changed.
void DistributedActiveSet::add_columns(Index changed) {
  if (static_cast<Index>(changes_.size()) > changed)
    throw Error("distributed active_set: the column update has more changes than the pass counted");
  const Index nx = grid_.nx, first = slab_.start * nx;
  std::size_t next = 0;
  operator_.apply(
      [&](Index r, double* row) {
        std::fill_n(row, nx, 0.0);
        const Index end = first + (r + 1) * nx;
        for (; next < changes_.size() && static_cast<Index>(changes_[next].node) < end; ++next)
          row[static_cast<Index>(changes_[next].node) - first - r * nx] = changes_[next].dp;
      },
      [&](Index r, const double* row) {
        double* const u = u_.data() + r * nx;
        for (Index x = 0; x < nx; ++x)
          u[x] += row[x];
      });
  displacement_fresh_ = false;
}

void DistributedActiveSet::scale_pressure(std::vector<double>& p, double factor) {
  for (std::size_t k = 0; k < n_; ++k)
    if (!plastic_[k]) p[k] = factor * p[k];
  displacement_current_ = false;
}

bool DistributedActiveSet::scale_to(std::vector<double>& p, double total) {
  const Sums s = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k)
      if (plastic_[k])
        part.g += cap_;
      else
        part.a += p[k];
  });
  double factor = 1;
  if (!load_scale(s.a, s.g, total, factor)) return false;
  if (displacement_current_ && s.g == 0)
    scale_with_displacement(p, factor);
  else
    scale_pressure(p, factor);
  return true;
}

void DistributedActiveSet::scale_with_displacement(std::vector<double>& p, double factor) {
  for (std::size_t k = 0; k < n_; ++k) {
    p[k] = factor * p[k];
    u_[k] = factor * u_[k];
  }
}

DistributedActiveSet::Sums DistributedActiveSet::update_sets(std::vector<double>& p, double d, double limit,
                                                             double entry, bool capping) {
  changes_.clear();
  return over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k) {
      const double g = d + u_[k] - h_[k];
      bool elastic = in_[k], plastic = plastic_[k];
      if (elastic) {
        part.e = std::max(part.e, std::abs(g));
        part.d += p[k] > cap_ ? 1.0 : 0.0;
        elastic = p[k] >= 0 && (p[k] <= cap_ || !capping);
        plastic = p[k] > cap_ && capping;
      } else if (plastic) {
        plastic = g <= limit;
        elastic = !plastic;
      } else {
        elastic = g < -entry;
      }
      if (elastic != static_cast<bool>(in_[k]) || plastic != static_cast<bool>(plastic_[k])) {
        in_[k] = elastic;
        plastic_[k] = plastic;
        part.h += 1;
      }
      keep_to_sets(p, k, part);
    }
  });
}

// The inner CG (bem/solvers/active_set_inner_cg.cpp), its passes apart: the window sums over the halo, then
// the transform, then the element-wise work (the serial method rides them in the transform's callbacks).

template <class Value, class Emit>
void DistributedActiveSet::window_sums(Value value, Emit emit) {
  start_window_sums(value);
  for (Index r = 0; r < slab_.count; ++r)
    emit(r, window_sums_of(r, value));
}

// Only the rows other ranks read (those within the window's radius of the slab's edges) are made, straight
// into the exchange's send buffer; the slab's own rows are made from `value` as the window reaches them.
template <class Value>
void DistributedActiveSet::start_window_sums(Value value) {
  const Index nx = grid_.nx;
  halo_->exchange([&](Index r, double* out) {
    for (Index x = 0; x < nx; ++x)
      out[x] = value(static_cast<std::size_t>(r * nx + x));
  });
  window_.restart();
}

template <class Value>
const double* DistributedActiveSet::window_sums_of(Index r, Value value) {
  const Index nx = grid_.nx;
  auto value_row = [&](Index y, double* out) {
    const Index local = y - slab_.start;
    if (local >= 0 && local < slab_.count) {
      for (Index x = 0; x < nx; ++x)
        out[x] = value(static_cast<std::size_t>(local * nx + x));
    } else {
      std::copy_n(halo_->row(y), nx, out);
    }
  };
  return window_.sums(slab_.start + r, value_row);
}

// The gathered values of every rank, `count` each, in rank order (a buffer kept between calls).
const std::vector<double>& DistributedActiveSet::gathered(const double* mine, int count) const {
  gathered_.resize(static_cast<std::size_t>(count * size_of(comm_)));
  MPI_Allgather(mine, count, MPI_DOUBLE, gathered_.data(), count, MPI_DOUBLE, comm_);
  return gathered_;
}

Index DistributedActiveSet::cg_on_set(std::vector<double>& p, double scale, double reduction, double absolute,
                                      double step_change, Index budget,
                                      const std::function<void()>& between) {
  const Sums count = count_on_set(p, scale);
  set_size_ = count.c;
  set_mean_ = 0;
  if (set_size_ == 0) return 0;
  CgStep step;
  step.radius = extension_radius();
  const double start_shift = load_control_ ? count.a / set_size_ : -separation_;
  const Sums start = over_points([&, start_shift](std::size_t begin, std::size_t end, Sums& part) {
    part.e = part.f = -kInfinity;
    for (std::size_t k = begin; k < end; ++k)
      if (in_[k]) {
        r_[k] = u_[k] - h_[k] - start_shift;
        add_residual(part, r_[k]);
      }
  });
  double norm = 0, largest = 0;
  auto settle = [&](const Sums& s) {
    const double shift = load_control_ ? s.a / set_size_ : 0.0;
    step.c += shift;
    norm = std::sqrt(std::max(s.b - 2 * shift * s.a + set_size_ * shift * shift, 0.0));
    largest = std::max(s.e - shift, s.f + shift);
  };
  settle(start);
  const double r0 = norm;
  double rz_old = 0;
  Index iterations = 0;
  last_step_change_ = 0;
  for (; iterations < budget; ++iterations) {
    const bool within = largest <= absolute && (reduction > 0 || last_step_change_ <= step_change);
    if (within || norm <= reduction * r0 || norm == 0) break;
    if (between) between();
    if (iterations == 0 && step.radius > 0) make_extension_weights(step.radius);
    step.shift_c = step.c;
    step.to_filter = std::ldexp(1.0, -std::ilogb(largest));
    step.from_filter = std::ldexp(1.0, std::ilogb(largest));
    double z_sum = 0;
    step.rz = filter_pass(step, z_sum);
    step.zbar = load_control_ ? z_sum / set_size_ : 0.0;
    if (!(step.rz > 0)) break;
    step.beta = rz_old > 0 ? step.rz / rz_old : 0.0;
    rz_old = step.rz;
    const Sums f = operator_pass(p, step);
    displacement_fresh_ = false;
    if (!(step.t_gt > 0)) break;
    const double pressure_sum = f.d + count.g;
    last_step_change_ = pressure_sum > 0 ? f.c / pressure_sum : 0;
    settle(f);
  }
  set_mean_ = start_shift + step.c;
  return iterations;
}

DistributedActiveSet::Sums DistributedActiveSet::count_on_set(std::vector<double>& p, double scale) {
  auto rescaled = [&](std::size_t k) {
    if (scale != 1 && !plastic_[k]) p[k] = scale * p[k];
  };
  auto counted = [&](std::size_t k, Sums& part) {
    if (in_[k]) {
      part.a += u_[k] - h_[k];
      part.c += 1;
    }
    part.g += plastic_[k] ? p[k] : 0.0;
  };
  if (displacement_current_)
    return over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k) {
        rescaled(k);
        if (scale != 1) u_[k] = scale * u_[k];
        counted(k, part);
      }
    });
  return fresh_displacement(p, rescaled, counted);
}

// The extension's weights of this set, from the window counts of set nodes (the serial method updates them
// by the flips when few changed: the same integer counts and weights either way).
void DistributedActiveSet::make_extension_weights(Index radius) {
  const double floor = kExtensionFloor * static_cast<double>((2 * radius + 1) * (2 * radius + 1));
  const Index nx = grid_.nx;
  window_sums([&](std::size_t k) { return in_[k] ? 1.0 : 0.0; },
              [&](Index r, const double* sums) {
                for (Index x = 0; x < nx; ++x) {
                  const std::size_t k = static_cast<std::size_t>(r * nx + x);
                  window_count_[k] = static_cast<std::uint16_t>(sums[x]);
                  extension_weight_[k] = in_[k] ? 0.0f : static_cast<float>(1 / std::max(sums[x], floor));
                }
              });
}

// Filter: E r into the filter (rounded to float, as the serial single-precision filter's input), F E r out
// (rounded to float, as its output), z kept on the set and weighted off it. Returns <E r, F E r> scaled
// back; z_sum: the sum on the set that E^T will leave. As the serial filter pass: the window sums and the
// input ride in the transform's producer, <E r, F E r> is the transform's spectral product, z is made in its
// consumer.
double DistributedActiveSet::filter_pass(const CgStep& step, double& z_sum) {
  const Index nx = grid_.nx, radius = step.radius;
  const double cc = step.shift_c;
  auto window_input = [&](std::size_t k) { return (in_[k] ? r_[k] : cc) - cc; };
  if (radius > 0) start_window_sums(window_input);
  double sums[2] = {0, 0};  // <E r, F E r> in the filter's scale, the sum on the set after E^T
  auto produce = [&](Index r, double* row) {
    const double* window = radius > 0 ? window_sums_of(r, window_input) : nullptr;
    for (Index x = 0; x < nx; ++x) {
      const std::size_t k = static_cast<std::size_t>(r * nx + x);
      const double off_set = radius > 0 ? window[x] * static_cast<double>(extension_weight_[k]) : 0.0;
      const double on_set = r_[k] - cc;
      row[x] = static_cast<float>((in_[k] ? on_set : off_set) * step.to_filter);
    }
  };
  auto consume = [&](Index r, const double* row) {
    double row_sum = 0;
    for (Index x = 0; x < nx; ++x) {
      const std::size_t k = static_cast<std::size_t>(r * nx + x);
      const double filtered = static_cast<double>(static_cast<float>(row[x])) * step.from_filter;
      const double w = static_cast<double>(extension_weight_[k]);
      z_[k] = in_[k] ? filtered : (radius > 0 ? filtered * w : 0.0);
      const double times = radius > 0 ? static_cast<double>(window_count_[k]) : 0.0;
      row_sum += z_[k] * (in_[k] ? 1.0 : times);
    }
    sums[1] += row_sum;
  };
  filter_->apply(produce, consume, [&](double energy) { sums[0] = energy; });
  const std::vector<double>& all = gathered(sums, 2);
  double rz = 0;
  z_sum = 0;
  for (int r = 0; r < size_of(comm_); ++r) {
    rz += all[static_cast<std::size_t>(2 * r)];
    z_sum += all[static_cast<std::size_t>(2 * r + 1)];
  }
  return rz * step.from_filter * step.from_filter;
}

// Operator: the direction t = (E^T z - zbar) + beta t on the set, G t, the step tau = <r, z> / <t, G t>,
// then p -= tau t, u -= tau G t, r -= tau G t and the sums of the new residual and the pressure's change.
// As the serial operator pass: t is made in the transform's producer (E^T's window sums riding there), <t,
// G t> from the spectrum before the inverse transform, and the steps in its consumer.
DistributedActiveSet::Sums DistributedActiveSet::operator_pass(std::vector<double>& p, CgStep& step) {
  const Index nx = grid_.nx, radius = step.radius;
  auto window_input = [&](std::size_t k) { return in_[k] ? 0.0 : z_[k]; };
  if (radius > 0) start_window_sums(window_input);
  auto produce = [&](Index r, double* row) {
    const double* window = radius > 0 ? window_sums_of(r, window_input) : nullptr;
    for (Index x = 0; x < nx; ++x) {
      const std::size_t k = static_cast<std::size_t>(r * nx + x);
      if (in_[k]) {
        const double zk = z_[k] + (radius > 0 ? window[x] : 0.0);
        t_[k] = (zk - step.zbar) + step.beta * t_[k];
        row[x] = t_[k];
      } else {
        row[x] = 0;
      }
    }
  };
  auto multiplied = [&](double energy) {
    const std::vector<double>& all = gathered(&energy, 1);
    step.t_gt = 0;
    for (const double v : all)
      step.t_gt += v;
    step.tau = step.t_gt > 0 ? step.rz / step.t_gt : 0.0;
  };
  Sums s;
  s.e = s.f = -kInfinity;
  auto consume = [&](Index r, const double* row) {
    const double tau = step.tau, shift = step.c;
    double moved = 0, sum = 0;
    for (Index x = 0; x < nx; ++x) {
      const std::size_t k = static_cast<std::size_t>(r * nx + x);
      const double w = row[x];
      u_[k] -= tau * w;
      if (in_[k]) {
        const double change = tau * t_[k];
        moved += std::abs(change);
        p[k] -= change;
        sum += std::abs(p[k]);
        r_[k] -= tau * w;
        add_residual(s, r_[k] - shift);
      }
    }
    s.c += moved;
    s.d += sum;
  };
  operator_.apply(produce, consume, multiplied);
  return reduced(s);
}

// The starts (bem/solvers/active_set_coarse_start.cpp).

double DistributedActiveSet::start_scale(const std::vector<double>& p, double total) {
  const Sums s = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k)
      part.a += p[k];
  });
  return s.a > 0 ? total / s.a : 0;
}

double DistributedActiveSet::start_displacement(std::vector<double>& p, double factor) {
  const Sums set = fresh_displacement(
      p,
      [&](std::size_t k) {
        if (factor != 1) p[k] = factor * p[k];
      },
      [&](std::size_t k, Sums& part) {
        in_[k] = p[k] > 0;
        if (in_[k]) {
          part.a += u_[k] - h_[k];
          part.b += 1;
        }
      });
  return flat_height(set);
}

// A cold start under load control keeps at most as many nodes as the coarse level has in contact, those of
// the largest scores: the lowest score kept (kth_largest_over_ranks: std::nth_element's value), 0 when all
// are.
double DistributedActiveSet::coarse_area_level(const std::vector<double>& scores) {
  const double candidates = sum_over_ranks(static_cast<double>(scores.size()), comm_);
  const auto most = static_cast<std::size_t>(coarse_fraction_ * points_);
  if (most == 0 || static_cast<double>(most) >= candidates) return 0;
  return kth_largest_over_ranks(scores, most, comm_);
}

ActiveSetOutcome DistributedActiveSet::nested_start(const ActiveSetProblem& problem, std::vector<double>& p,
                                                    const std::function<void()>& between) {
  if (!has_coarse_) {
    p.assign(n_, 1.0);
    if (!problem.load_control) {
      const double stiffness = 1 / operator_.self_response();
      for (std::size_t k = 0; k < n_; ++k)
        p[k] = std::min(std::max(h_[k] - problem.separation, 0.0) * stiffness, problem.hardness);
    }
    return {};
  }
  // The coarse level lives for this start only: its fields are not held while this level iterates.
  Coarse coarse(grid_, h_, modulus_, comm_, threads_, gather_bound_);
  const ActiveSetOutcome outcome = coarse.solve(problem, slab_, cap_, p, coarse_fraction_, between);
  coarse_peak_ = std::max(coarse_peak_, coarse.bytes());
  return outcome;
}

DistributedActiveSet::Sums DistributedActiveSet::start_sets(std::vector<double>& p, bool warm, double total,
                                                            double& d) {
  const double factor = load_control_ ? start_scale(p, total) : 1.0;
  const double start_flat = start_displacement(p, factor);
  d = load_control_ ? start_flat : separation_;
  if (!warm) {
    const double stiffness = 1 / operator_.self_response();
    std::vector<double> scores;
    for (std::size_t k = 0; k < n_; ++k) {
      const double score = start_score(p, k, d, stiffness);
      in_[k] = score > 0;
      if (in_[k] && load_control_ && has_coarse_) scores.push_back(score);
    }
    const double level = load_control_ && has_coarse_ ? coarse_area_level(scores) : 0.0;
    if (level > 0)
      for (std::size_t k = 0; k < n_; ++k)
        if (in_[k]) in_[k] = start_score(p, k, d, stiffness) >= level;
  }
  changes_.clear();
  Sums kept = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
    for (std::size_t k = begin; k < end; ++k) {
      plastic_[k] = in_[k] && p[k] >= cap_;
      in_[k] = in_[k] && !plastic_[k];
      keep_to_sets(p, k, part);
    }
  });
  if (kept.b == 0 && kept.g == 0) {
    changes_.clear();
    kept = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k) {
        in_[k] = load_control_ || h_[k] > separation_;
        keep_to_sets(p, k, part);
      }
    });
  }
  return kept;
}

}  // namespace contactbench::mpi
