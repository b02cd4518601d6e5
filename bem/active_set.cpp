#include "contactbench/bem/active_set.hpp"

#include <omp.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>

#include "contactbench/bem/box_sum.hpp"
#include "contactbench/bem/convolution.hpp"
#include "contactbench/bem/fourier_preconditioner.hpp"
#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// Inner solves stop at this relative reduction of the residual's L2 norm while the set still changes: a
// looser one needs more outer steps, a tighter one solves exactly on a set about to change (measured with a
// numpy prototype on surface A and an H = 0.8 surface, 256^2 to 1024^2: 0.1 among 0.03 to 0.3).
constexpr double kInnerReduction = 0.1;
// The coarsest level of the nested start, and the tolerance its levels are solved to (a start only).
constexpr Index kCoarsest = 64;
constexpr double kCoarseTolerance = 1e-3;
// The CG's displacement u (stepped, not made afresh) is kept as the output's when its drift from G p is
// this many times below the convergence threshold.
constexpr double kDriftMargin = 1000;
// A set update that changes at most this many pressures brings G p up to date by their columns of G (a
// pass over the grid: measured at 256^2, 1024^2 and 2048^2, 16 nodes cost about half a fresh G p, periodic,
// and a quarter non-periodic; one node a tenth) instead of a fresh transform.
constexpr std::size_t kFewChanges = 16;
// A guard against a set that cycles: at most this many outer steps (each ends an inner solve).
constexpr Index kMaxOuter = 500;
// Nodes enter the contact set when they penetrate beyond the gap's round-off for this many outer steps, then
// only beyond the convergence threshold (docs/solvers.md "Which nodes enter"): a node at p = 0 and g = 0
// within the solve's accuracy could otherwise enter and leave again for ever. Solves in tests/ take 5 to 16
// outer steps.
constexpr Index kLaxEntrySteps = 30;
// The extended filter (docs/solvers.md "The extended filter"): the residual is extended off the contact set
// by its average over the set nodes of a (2 kExtensionRadius + 1)^2 window before the Fourier filter, and the
// filter's output gathered back by the transpose. The average divides by the window's count of set nodes,
// but by at least kExtensionFloor of the window, so that a node with few set nodes near it gets a damped
// value, not one node's residual. Measured with `contactbench bem` at 1024^2 (surface A refined and an
// H = 0.8 surface, 1 %, 10 % and 30 % contact, seven cases): 210 / 197 / 191 / 195 iterations in all for
// radii 6 / 8 / 12 / 16, against 357 without the extension.
constexpr Index kExtensionRadius = 12;
constexpr double kExtensionFloor = 0.25;
// The preconditioner's filter runs in single precision, on plans FFTW estimates: measured float plans
// applied 3 % faster in the solve (surface A at 1024^2, 1 %, periodic: 0.159-0.168 s against 0.164-0.177 s)
// but cost about 1.1 s to make per process at 1024^2 (the double filter shared the operator's measured
// plans), which a scene of a few dozen solves never earns back (the paper's default scene: 7.1 s against
// 6.4 s before the float filter).
constexpr FftRigor kFilterPlans = FftRigor::estimate;
// The window counts kept with the weights are 16-bit (ActiveSet::window_count_).
static_assert((2 * kExtensionRadius + 1) * (2 * kExtensionRadius + 1) <=
              std::numeric_limits<std::uint16_t>::max());

// Sums over a row of nx points of z on the contact set (in), with and without the transpose of the
// extension. E^T adds to each set node the window sum of z off the set, so each off-set z is added once per
// set node in its window (count, the window's count of set nodes): the sum on the set after E^T, made while
// z is written, before the transpose itself runs.
template <class T>
double sum_after_transpose(const std::uint8_t* in, const T* z, const std::uint16_t* count, Index nx) {
  double sum = 0;
#pragma omp simd reduction(+ : sum)
  for (Index x = 0; x < nx; ++x) {
    const double times = count[x];  // (loaded whatever in[x]: the loop vectorises)
    sum += static_cast<double>(z[x]) * (in[x] ? 1.0 : times);
  }
  return sum;
}
template <class T>
double sum_on_set(const std::uint8_t* in, const T* z, Index nx) {
  double sum = 0;
#pragma omp simd reduction(+ : sum)
  for (Index x = 0; x < nx; ++x) {
    const double value = z[x];
    sum += in[x] ? value : 0.0;
  }
  return sum;
}

// Coarse pixel values on the fine grid: bilinear between coarse pixel centres (fine pixel 2y + a sits at
// coarse coordinate y + (2a - 1)/4), wrapped when periodic, clamped at the edges otherwise; each value then
// clamped to [0, cap]. Rows split over `threads` threads.
template <class T>
std::vector<T> interpolate_up(const std::vector<T>& coarse, Index cnx, Index cny, bool periodic, T cap,
                              int threads) {
  auto neighbour = [periodic](Index i, Index step, Index n) {
    const Index j = i + step;
    if (periodic) return (j + n) % n;
    return std::clamp<Index>(j, 0, n - 1);
  };
  const Index nx = 2 * cnx, ny = 2 * cny;
  std::vector<T> rows(static_cast<std::size_t>(cny * nx));
  std::vector<T> fine(static_cast<std::size_t>(ny * nx));
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static)
    for (Index y = 0; y < cny; ++y)
      for (Index x = 0; x < nx; ++x) {
        const Index c = x / 2, other = neighbour(c, x % 2 == 0 ? -1 : 1, cnx);
        rows[static_cast<std::size_t>(y * nx + x)] =
            static_cast<T>(0.75 * static_cast<double>(coarse[static_cast<std::size_t>(y * cnx + c)]) +
                           0.25 * static_cast<double>(coarse[static_cast<std::size_t>(y * cnx + other)]));
      }
#pragma omp for schedule(static)
    for (Index y = 0; y < ny; ++y) {
      const Index c = y / 2, other = neighbour(c, y % 2 == 0 ? -1 : 1, cny);
      for (Index x = 0; x < nx; ++x)
        fine[static_cast<std::size_t>(y * nx + x)] = std::clamp(
            static_cast<T>(0.75 * static_cast<double>(rows[static_cast<std::size_t>(c * nx + x)]) +
                           0.25 * static_cast<double>(rows[static_cast<std::size_t>(other * nx + x)])),
            T(0), cap);
    }
  }
  return fine;
}

template <class T>
class ActiveSet {
 public:
  ActiveSet(const Grid& grid, std::vector<T> heights, Real modulus, int threads)
      : grid_(grid),
        h_(std::move(heights)),
        modulus_(modulus),
        threads_(threads),
        operator_(make_half_space_convolution<T>(grid, modulus, threads)),
        filter_(make_unit_fourier_preconditioner<float>(grid, threads, kFilterPlans)),
        n_(static_cast<std::size_t>(grid.points())),
        u_(n_),
        r_(n_),
        z_(n_),
        t_(n_),
        extension_weight_(n_),
        in_(n_),
        plastic_(n_),
        sums_(static_cast<std::size_t>(std::max({operator_->threads(), filter_->threads(), threads}))) {
    const auto [low, high] = std::minmax_element(h_.begin(), h_.end());
    highest_ = static_cast<double>(*high);
    // The round-off of a gap d - h + u: a few epsilons of T of the largest height.
    gap_round_off_ = 8 * static_cast<double>(std::numeric_limits<T>::epsilon()) *
                     std::max(std::abs(static_cast<double>(*low)), std::abs(highest_));
    height_range_ = highest_ - static_cast<double>(*low);
    if (!(height_range_ > 0)) height_range_ = 1;  // a flat surface: relative to 1 m, as ContactSolution
    make_coarse_level();                          // the whole hierarchy, with its FFT plans, made once
    for (int thread = 0; thread < team(); ++thread)
      window_rows_.emplace_back(grid_.nx, grid_.ny, extension_radius(), grid_.periodic);
    changes_.resize(sums_.size());
    flips_.resize(sums_.size());
    window_count_.resize(n_);
    response_.assign(n_, T(0));
    std::vector<T> unit(n_, T(0));
    unit[0] = T(1);
    operator_->apply(unit.data(), response_.data());
  }

  ActiveSetOutcome solve(const ActiveSetProblem& problem, double tolerance, Index max_iterations, bool warm,
                         std::vector<T>& p, const std::function<void()>& between) {
    ActiveSetOutcome outcome;
    load_control_ = problem.load_control;
    separation_ = problem.separation;
    cap_ = std::isfinite(problem.hardness) ? static_cast<T>(problem.hardness)
                                           : std::numeric_limits<T>::infinity();
    const double total = problem.mean_pressure * static_cast<double>(n_);
    displacement_current_ = displacement_fresh_ = false;
    weights_current_ = false;  // the starts below make new sets
    if (!warm) {
      const ActiveSetOutcome coarse = nested_start(problem, p, between);
      outcome.coarse_iterations = coarse.iterations;
      outcome.work = coarse.work / 4;  // a coarse level's iteration costs a quarter of a fine one
    }
    // The starting sets. Cold: {p - k g > 0}, k the stiffness of one pixel, g the gap of the nested start
    // (under load control with the flat from its mean on the start's own contact set), under load control
    // cut to the coarse level's contact area (coarse_area_level). Warm: the start's own contact set {p > 0},
    // the previous solution's: under a growing load the set of the rule above overshoots (the scaled
    // previous pressure presses the flat too deep; surface A at 256^2, load 0.001 -> 0.002: 8673 nodes for
    // the 2472 of the solution), and the outer steps that shrink it back cost more than those that grow the
    // previous set (10-load curve: 0.81-0.92 of the cold solves' iterations at 256^2 and 512^2 against
    // 0.88-1.10; about 1 at 1024^2, where the cold nested start is as good; docs/solvers.md). Of those,
    // the nodes at or above the hardness start plastic. The start's G p is made with p scaled to the load
    // on its way in and the set {p > 0} with its mean of u - h on the way out.
    const double factor = load_control_ ? start_scale(p, total) : 1.0;
    const double start_flat = start_displacement(p, factor);
    double d = load_control_ ? start_flat : separation_;
    if (!warm) {
      const double stiffness = 1 / operator_->self_response();
      const std::size_t candidates = score_start(p, d, stiffness);
      const T level = load_control_ && coarse_ ? coarse_area_level(candidates) : T(0);
      if (level > 0)
        over_points([&](std::size_t begin, std::size_t end, Sums&) {
          for (std::size_t k = begin; k < end; ++k)
            if (in_[k]) in_[k] = start_score(p, k, d, stiffness) >= level;  // the same operation as ranked
        });
    }
    // The starting sets' plastic nodes, and the pressure held to the sets; from here each set update holds
    // p to its new sets in its own pass.
    Sums kept = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k) {
        plastic_[k] = in_[k] && p[k] >= cap_;
        in_[k] = in_[k] && !plastic_[k];
        keep_to_sets(p, k, part);
      }
    });
    if (kept.b == 0 && kept.g == 0) {  // load control: every node; separation control: those the flat
      kept = over_points([&](std::size_t begin, std::size_t end, Sums& part) {  // penetrates
        for (std::size_t k = begin; k < end; ++k) {
          in_[k] = load_control_ || static_cast<double>(h_[k]) > separation_;
          keep_to_sets(p, k, part);
        }
      });
    }

    // A cold start caps only once the elastic sets have settled: the first inner solves, far from the
    // solution, give a few nodes pressures many times the load's, which as plastic nodes would carry more
    // than the load (a 128^2 rough surface with H at half the elastic peak then cycled for ever). From the
    // settled elastic solution, the nodes above H carry more than H each, so the elastic ones keep a positive
    // share.
    bool capping = warm;
    bool final = false;
    Index inner = 0, fresh = 0, column_updates = 0;
    for (Index outer = 1; outer <= kMaxOuter; ++outer) {
      // The linear problem on the elastic set, from the current pressure kept on it (scaled to the load less
      // what the plastic nodes carry, under load control), p = H on the plastic set, 0 elsewhere. Only nodes
      // that left the set or became plastic changed their pressure: when none did (nodes only entered, at
      // p = 0, or nothing changed), the displacement stays G p and the CG needs no fresh one; when a few
      // did, their columns of G bring it up to date (cheaper than a transform up to kFewChanges nodes).
      if (kept.c > 0) {
        if (displacement_current_ && kept.c <= kFewChanges) {
          add_columns();  // u += G (p after - p before), the few nodes' columns of G
          ++column_updates;
        } else {
          displacement_current_ = displacement_fresh_ = false;
        }
      }
      double scale = 1;  // the load's rescaling, made by the CG in its first pass when it can be
      if (load_control_) {
        const bool unloaded = !(kept.a > 0);
        if (unloaded) {
          for (std::size_t k = 0; k < n_; ++k)
            if (in_[k]) p[k] = T(1);
          displacement_current_ = displacement_fresh_ = false;
        }
        // No elastic node leaves the flat's height undetermined, and plastic nodes carrying the load or
        // more leave nothing for the elastic ones (a very soft contact): the sets are made again.
        const bool scalable =
            kept.b > 0 && (unloaded ? scale_to(p, total) : load_scale(kept.a, kept.g, total, scale));
        if (!scalable) {
          reseat(p, total);
          scale_to(p, total);
          scale = 1;
        } else if (scale != 1 && kept.g > 0) {
          displacement_current_ = displacement_fresh_ = false;  // G p does not scale with p: made afresh
        }
      }
      fresh += displacement_current_ ? 0 : 1;
      const Index steps = cg_on_set(p, scale, final ? 0.0 : kInnerReduction, threshold(tolerance, d),
                                    final ? tolerance : 0.0, max_iterations - inner - fresh, between);
      inner += steps;
      // The set update, from the CG's own displacement (updated with each step; a fresh one costs an
      // application of G, made at the end unless the last outer step's start made it) and the flat's
      // height from the CG's own mean of u - h on the set.
      d = load_control_ ? -set_mean_ : separation_;
      // Nodes enter when they penetrate beyond the gap's round-off (beyond the threshold once kLaxEntrySteps
      // outer steps have passed), leave when their pressure is negative. Entering only beyond the threshold
      // left out every node that penetrates by less: an area biased low by a number of nodes that grows
      // with the grid on a pixel-rough surface. Elastic nodes above the hardness become plastic; plastic
      // nodes whose gap opens by more than the threshold become elastic again.
      const double limit = threshold(tolerance, d);
      const double entry = outer <= kLaxEntrySteps ? gap_round_off_ : limit;
      for (auto& log : flips_)
        log.clear();
      const Sums update = over_points([&, d, limit, entry](std::size_t begin, std::size_t end, Sums& part) {
        for (std::size_t k = begin; k < end; ++k) {
          const double g = d + static_cast<double>(u_[k]) - static_cast<double>(h_[k]);
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
            if (elastic != static_cast<bool>(in_[k])) log_flip(k, elastic);
            in_[k] = elastic;
            plastic_[k] = plastic;
            part.h += 1;
          }
          keep_to_sets(p, k, part);  // for the next outer step, or the output's clipping below
        }
      });
      note_flips();
      const double residual = update.e;
      const Index changed = static_cast<Index>(update.h);
      kept = update;
      outcome.outer = outer;
      outcome.residual = residual / height_range_;
      outcome.change = last_step_change_;
      // Counted: the CG's iterations, the fresh displacements of the CG's starts and the starting set's gap
      // (and below the final gap), each application of G as a whole iteration.
      outcome.iterations = inner + fresh + 1;
      const bool above_cap = update.d > 0;
      if (changed == 0 && !above_cap && residual <= limit && last_step_change_ <= tolerance) {
        outcome.converged = true;
        break;
      }
      if (changed == 0 && above_cap && !capping) {
        capping = true;  // the elastic sets settled with pressures above H: now the plastic set
        final = false;
        continue;
      }
      if (changed == 0 && final && steps == 0) break;  // no descent left above the tolerance: stalled
      final = changed == 0;  // the sets settled: the next inner solve runs to the tolerance
      if (outcome.iterations >= max_iterations) break;
    }
    // The pressure of the sets it ends on (on convergence, nothing is clipped: 0 < p <= H on the elastic
    // set), its gap.
    const Sums held = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k)
        if (in_[k]) {
          const T clamped = std::clamp(p[k], T(0), cap_);
          part.c += clamped != p[k] ? 1.0 : 0.0;
          p[k] = clamped;
        }
    });
    const bool clipped = kept.c > 0 || held.c > 0;  // (kept: the last update's holding p to its sets)
    if (clipped && load_control_) scale_to(p, total);
    // The gap of the output afresh when u could have drifted from G p by a part of the threshold: after a
    // clipping (u is no longer G p), or when the drift of u updated `inner` times by the CG's steps (and a
    // few times by columns of G), at most about that many epsilons of the height range (measured at
    // 1024^2, 10 to 22 steps: 0.25 to 1 of it, in double and in float), comes within a thousandth of the
    // threshold (single precision, or a solve near round-off such as the 1e-12 references). In double at
    // the tolerances of use a fresh G p would change the gap by 1e-15 of the height range against a
    // threshold of 1e-8 of the approach.
    const double drift = static_cast<double>(inner + column_updates + 1) *
                         static_cast<double>(std::numeric_limits<T>::epsilon()) * height_range_;
    const bool drifted = !displacement_fresh_ && kDriftMargin * drift > threshold(tolerance, d);
    if (clipped || !displacement_current_ || drifted) {
      operator_->apply(p.data(), u_.data());
      displacement_current_ = displacement_fresh_ = true;
      ++outcome.iterations;
    }
    // The elastic set {p > 0} less the plastic nodes, the flat's height from its mean of u - h, the nodes
    // touching (elastic or plastic) and the sum of p.
    const Sums last = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k) {
        in_[k] = p[k] > 0 && !plastic_[k];
        part.d += in_[k] || plastic_[k] ? 1.0 : 0.0;
        part.g += static_cast<double>(p[k]);
        if (in_[k]) {
          part.a += static_cast<double>(u_[k]) - static_cast<double>(h_[k]);
          part.b += 1;
        }
      }
    });
    outcome.separation = load_control_ ? flat_height(last) : separation_;
    outcome.pressure_sum = last.g;
    contact_fraction_ = last.d / static_cast<double>(n_);
    outcome.work += static_cast<double>(outcome.iterations);
    outcome.iterations = std::llround(outcome.work);
    return outcome;
  }

  // G p - h of the last solution.
  void displacement_minus_heights(std::vector<T>& out) {
    out.resize(n_);
    over_points([&](std::size_t begin, std::size_t end, Sums&) {
      for (std::size_t k = begin; k < end; ++k)
        out[k] = u_[k] - h_[k];
    });
  }

 private:
  // The largest |gap| accepted on the contact set: the tolerance times the approach of the highest point,
  // max h - d (> 0 in contact; the gaps that matter are of its order, while the height range can be made
  // of a pit nothing touches), but not below the gap's round-off.
  double threshold(double tolerance, double d) const {
    return std::max(tolerance * (highest_ - d), gap_round_off_);
  }

  int team() const { return static_cast<int>(sums_.size()); }
  // The next window sums start afresh (their inputs changed).
  void restart_windows() {
    for (WindowRows& window : window_rows_)
      window.restart();
  }
  Index extension_radius() const {
    return std::min(kExtensionRadius, (std::min(grid_.nx, grid_.ny) - 1) / 2);
  }

  // Per-thread sums of a pass (one cache line each), combined in thread order: for a fixed thread count
  // the same every run.
  struct alignas(64) Sums {
    double a = 0, b = 0, c = 0, d = 0, g = 0, h = 0;  // combined as sums
    double e = 0, f = 0;                              // combined as maxima

    void add(const Sums& o) {
      a += o.a;
      b += o.b;
      c += o.c;
      d += o.d;
      g += o.g;
      h += o.h;
      e = std::max(e, o.e);
      f = std::max(f, o.f);
    }
  };

  Sums combined() const {
    Sums all;
    all.e = all.f = -std::numeric_limits<double>::infinity();
    for (const Sums& s : sums_)
      all.add(s);
    return all;
  }

  // Runs body(begin, end, sums) on a static split of the points over the team; returns the combined sums.
  // Each thread's sums are a local object until its body ends: sums kept in sums_ through the loop would be
  // reloaded and stored again after every store to an array (they might alias).
  template <class Body>
  Sums over_points(Body body) {
    for (Sums& s : sums_)
      s = Sums{};
#pragma omp parallel num_threads(static_cast <int>(sums_.size()))
    {
      const std::size_t thread = static_cast<std::size_t>(omp_get_thread_num());
      const std::size_t team = static_cast<std::size_t>(omp_get_num_threads());
      Sums local;
      body(n_ * thread / team, n_ * (thread + 1) / team, local);
      sums_[thread] = local;
    }
    return combined();
  }

  // The factor that scales the start's pressure to the load (no plastic nodes yet): total over its sum, 0
  // when that is 0.
  double start_scale(const std::vector<T>& p, double total) {
    const Sums s = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k)
        part.a += static_cast<double>(p[k]);
    });
    return s.a > 0 ? total / s.a : 0;
  }

  // The start's displacement: u = G p with p times `factor` on its way in, and on u's way out the elastic
  // set {p > 0}; returns the flat's height from the mean of u - h on that set.
  double start_displacement(std::vector<T>& p, double factor) {
    const Sums set = fresh_displacement(
        p,
        [&](std::size_t k) {
          if (factor != 1) p[k] = static_cast<T>(factor * static_cast<double>(p[k]));
        },
        [&](std::size_t k, Sums& part) {
          in_[k] = p[k] > 0;
          if (in_[k]) {
            part.a += static_cast<double>(u_[k]) - static_cast<double>(h_[k]);
            part.b += 1;
          }
        });
    return flat_height(set);
  }

  // u = G p, made afresh, with per-point work riding along: on_input(k) before p[k] goes into the transform
  // (it may change p[k]), on_output(k, sums) once u[k] is written. Returns the combined sums.
  template <class Input, class Output>
  Sums fresh_displacement(std::vector<T>& p, Input on_input, Output on_output) {
    const Index nx = grid_.nx;
    auto produce = [&](Index first, Index rows, T* buffer, Index ld, int) {
      for (Index y = 0; y < rows; ++y)
        for (Index x = 0; x < nx; ++x) {
          const std::size_t k = static_cast<std::size_t>((first + y) * nx + x);
          on_input(k);
          buffer[y * ld + x] = p[k];
        }
    };
    auto consume = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
      Sums part;  // local: see over_points
      for (Index y = 0; y < rows; ++y)
        for (Index x = 0; x < nx; ++x) {
          const std::size_t k = static_cast<std::size_t>((first + y) * nx + x);
          u_[k] = buffer[y * ld + x];
          on_output(k, part);
        }
      sums_[static_cast<std::size_t>(thread)].add(part);
    };
    for (Sums& s : sums_)
      s = Sums{};
    operator_->apply(typename Convolution<T>::Producer(produce), typename Convolution<T>::Consumer(consume));
    displacement_current_ = displacement_fresh_ = true;
    return combined();
  }

  // The flat's height that makes the gap zero-mean on a set, from the sum of u - h there (a) and its nodes
  // (b): d = -mean(u - h); 0 for an empty set.
  static double flat_height(const Sums& s) {
    return s.b > 0 ? -s.a / s.b : 0;
  }

  // A cold start's set {p - k g > 0} (start_score); returns how many, their scores the first values of z_
  // (free until the CG). Each thread writes its nodes' scores from the start of its own range of z_, then
  // they are moved to the front in thread order.
  std::size_t score_start(const std::vector<T>& p, double d, double stiffness) {
    over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      std::size_t next = begin;
      for (std::size_t k = begin; k < end; ++k) {
        const T score = start_score(p, k, d, stiffness);
        in_[k] = score > 0;
        if (in_[k]) z_[next++] = score;
      }
      part.a = static_cast<double>(begin);  // exact: below 2^53
      part.b = static_cast<double>(next - begin);
    });
    std::size_t candidates = 0;
    for (const Sums& s : sums_) {
      const auto begin = static_cast<std::ptrdiff_t>(s.a), count = static_cast<std::ptrdiff_t>(s.b);
      std::copy(z_.begin() + begin, z_.begin() + begin + count,
                z_.begin() + static_cast<std::ptrdiff_t>(candidates));  // forward: never past its source
      candidates += static_cast<std::size_t>(count);
    }
    return candidates;
  }

  // A cold start's score of node k, p - k g (k the stiffness of one pixel): the node starts in contact when
  // it is positive.
  T start_score(const std::vector<T>& p, std::size_t k, double d, double stiffness) const {
    const double g = d + static_cast<double>(u_[k]) - static_cast<double>(h_[k]);
    return static_cast<T>(static_cast<double>(p[k]) - stiffness * g);
  }

  // A cold start under load control keeps at most as many nodes as the coarse level's solution has in
  // contact (its fraction of the nodes), those of the largest scores (the first `candidates` values of z_):
  // returns the lowest score kept, 0 when all are. At a given load a finer grid resolves more roughness and
  // touches less, or as much where the surface has none below the coarse pixel; the rule's set is larger
  // still, the interpolated pressure being spread over the coarse spots (surface A at 1024^2 and 1 %: 15016
  // nodes, the coarse area 13132, the solution's 12095). A start sized to the fine area extrapolated over
  // the levels cost more outer steps: the steps shrink a set faster than they grow one (docs/solvers.md).
  T coarse_area_level(std::size_t candidates) {
    const auto most = static_cast<std::size_t>(coarse_->contact_fraction_ * static_cast<double>(n_));
    if (most == 0 || most >= candidates) return T(0);
    const auto last = z_.begin() + static_cast<std::ptrdiff_t>(most - 1);
    std::nth_element(z_.begin(), last, z_.begin() + static_cast<std::ptrdiff_t>(candidates),
                     std::greater<>());
    return *last;
  }

  // The sets of the bearing area (the limit of a very soft contact), with the current displacement: the m
  // nodes the flat penetrates deepest (largest h - u) plastic, m the most whose pressure H stays below the
  // load (none without a hardness), and the next (or those tied with it) elastic with the rest of the load.
  void reseat(std::vector<T>& p, double total) {
    const double most = std::isfinite(static_cast<double>(cap_)) ? std::ceil(total / cap_) - 1 : 0.0;
    const std::size_t m = static_cast<std::size_t>(std::clamp(most, 0.0, static_cast<double>(n_ - 1)));
    operator_->apply(p.data(), u_.data());
    std::vector<T> ranked(n_);  // the depths h - u, partly sorted
    for (std::size_t k = 0; k < n_; ++k)
      ranked[k] = h_[k] - u_[k];
    std::nth_element(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(m), ranked.end(),
                     std::greater<>());
    const T level = ranked[m];
    for (std::size_t k = 0; k < n_; ++k) {
      const T depth = h_[k] - u_[k];  // as ranked: the same operation on the same values
      plastic_[k] = depth > level;
      in_[k] = depth == level;
      weights_current_ = false;
      p[k] = plastic_[k] ? cap_ : T(in_[k] ? 1 : 0);
    }
    displacement_current_ = displacement_fresh_ = false;
  }

  // Holds p at node k to the sets: H on the plastic set, 0 off both. Adds to `part` what the load's rescaling
  // needs, a: the sum of p on the elastic set, b: its nodes, g: the sum of p on the plastic set; and c: 1
  // when p changed.
  void keep_to_sets(std::vector<T>& p, std::size_t k, Sums& part) {
    const T before = p[k];
    const T held = plastic_[k] ? cap_ : (in_[k] ? before : T(0));
    if (held != before) {  // stored only when changed: most nodes keep p = 0, their memory untouched
      p[k] = held;
      part.c += 1;
      if (part.c <= kFewChanges)  // the first few of each thread, for add_columns
        changes_[static_cast<std::size_t>(omp_get_thread_num())][static_cast<std::size_t>(part.c) - 1] = {
            k, static_cast<double>(held) - static_cast<double>(before)};
    }
    part.a += in_[k] ? static_cast<double>(held) : 0.0;
    part.b += in_[k];
    part.g += plastic_[k] ? static_cast<double>(cap_) : 0.0;
  }

  // u += G dp for the changes of p that the last pass recorded with keep_to_sets (at most kFewChanges in
  // all; each thread's first ones, in sums_[thread].c): dp_k times G's column k, the response to a unit
  // pressure at node 0 (response_) shifted to node k (wrapped when periodic; mirrored otherwise: the
  // half-space's response depends on |dx| and |dy| only). u stays current, not fresh.
  void add_columns() {
    std::vector<Change> all;
    for (std::size_t thread = 0; thread < sums_.size(); ++thread)
      for (std::size_t i = 0; i < static_cast<std::size_t>(sums_[thread].c); ++i)
        all.push_back(changes_[thread][i]);
    const Index nx = grid_.nx, ny = grid_.ny;
    const bool periodic = grid_.periodic;
#pragma omp parallel for num_threads(team()) schedule(static)
    for (Index y = 0; y < ny; ++y) {
      T* const row = u_.data() + y * nx;
      for (const Change& change : all) {
        const Index ky = static_cast<Index>(change.node) / nx, kx = static_cast<Index>(change.node) % nx;
        const Index dy = periodic ? (y - ky + ny) % ny : std::abs(y - ky);
        const T* const column = response_.data() + dy * nx;
        const T dp = static_cast<T>(change.dp);
        if (periodic) {
          for (Index x = kx; x < nx; ++x)
            row[x] += dp * column[x - kx];
          for (Index x = 0; x < kx; ++x)
            row[x] += dp * column[x - kx + nx];
        } else {
          for (Index x = kx; x < nx; ++x)
            row[x] += dp * column[x - kx];
          for (Index x = 0; x < kx; ++x)
            row[x] += dp * column[kx - x];
        }
      }
    }
    displacement_fresh_ = false;
  }

  // The set's changes since the extension's weights were made, so that a few of them update the weights
  // in their windows instead of a window sum over the grid (kept only while they are few: each costs a
  // window of (2 radius + 1)^2 nodes on one thread; the same counts and weights either way).
  struct Flip {
    std::size_t node = 0;
    bool entered = false;
  };
  std::size_t few_flips() const {
    const std::size_t window = static_cast<std::size_t>(2 * extension_radius() + 1);
    return n_ / (4 * window * window);
  }
  // In the set update: node k leaves or enters the elastic set (each thread's first few kept).
  void log_flip(std::size_t k, bool entered) {
    auto& log = flips_[static_cast<std::size_t>(omp_get_thread_num())];
    if (log.size() <= few_flips()) log.push_back({k, entered});
  }
  // After the set update: its flips join those pending, or the weights are to be made afresh.
  void note_flips() {
    if (!weights_current_) return;
    std::size_t total = pending_flips_.size();
    for (const auto& log : flips_)
      total += log.size();
    if (total > few_flips()) {
      weights_current_ = false;
      pending_flips_.clear();
      return;
    }
    for (const auto& log : flips_)
      pending_flips_.insert(pending_flips_.end(), log.begin(), log.end());
  }
  // The window counts moved by the pending flips, then the weights of the nodes in their windows.
  template <class WeightOf>
  void update_weights(Index radius, WeightOf weight_of) {
    const Index nx = grid_.nx, ny = grid_.ny;
    const bool periodic = grid_.periodic;
    auto over_window = [&](std::size_t node, auto visit) {
      const Index ky = static_cast<Index>(node) / nx, kx = static_cast<Index>(node) % nx;
      for (Index dy = -radius; dy <= radius; ++dy) {
        Index y = ky + dy;
        if (periodic) y = (y + ny) % ny;
        if (y < 0 || y >= ny) continue;
        for (Index dx = -radius; dx <= radius; ++dx) {
          Index x = kx + dx;
          if (periodic) x = (x + nx) % nx;
          if (x < 0 || x >= nx) continue;
          visit(static_cast<std::size_t>(y * nx + x));
        }
      }
    };
    for (const Flip& flip : pending_flips_)
      over_window(flip.node, [&](std::size_t j) {
        window_count_[j] = static_cast<std::uint16_t>(window_count_[j] + (flip.entered ? 1 : -1));
      });
    for (const Flip& flip : pending_flips_)
      over_window(flip.node, [&](std::size_t j) {
        extension_weight_[j] = weight_of(j, static_cast<double>(window_count_[j]));
      });
  }

  // The factor on the elastic pressures (summing to `elastic`; the plastic ones to `plastic`) that makes
  // the sum of p `total`; false when the plastic nodes alone carry `total` or more.
  static bool load_scale(double elastic, double plastic, double total, double& factor) {
    const double elastic_total = total - plastic;
    if (plastic > 0 && !(elastic_total > 0)) return false;
    factor = elastic > 0 ? elastic_total / elastic : 0;
    return true;
  }

  // p off the plastic set times `factor`; G p is no longer current.
  void scale_pressure(std::vector<T>& p, double factor) {
    over_points([&](std::size_t begin, std::size_t end, Sums&) {
      for (std::size_t k = begin; k < end; ++k)
        if (!plastic_[k]) p[k] = static_cast<T>(factor * static_cast<double>(p[k]));
    });
    displacement_current_ = false;
  }

  // The pressures off the plastic set scaled so that the sum of p is `total` (the plastic nodes at H);
  // false, and nothing changed, when the plastic nodes alone carry `total` or more.
  bool scale_to(std::vector<T>& p, double total) {
    const Sums s = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
      for (std::size_t k = begin; k < end; ++k)
        if (plastic_[k])
          part.g += static_cast<double>(cap_);
        else
          part.a += static_cast<double>(p[k]);
    });
    double factor = 1;
    if (!load_scale(s.a, s.g, total, factor)) return false;
    // Without plastic nodes G p scales with p; with them only the elastic nodes' share does.
    if (displacement_current_ && s.g == 0)
      scale_with_displacement(p, factor);
    else
      scale_pressure(p, factor);
    return true;
  }

  // p and u = G p (no plastic nodes) times `factor`: u stays G p, as fresh as before to one rounding.
  void scale_with_displacement(std::vector<T>& p, double factor) {
    over_points([&](std::size_t begin, std::size_t end, Sums&) {
      for (std::size_t k = begin; k < end; ++k) {
        p[k] = static_cast<T>(factor * static_cast<double>(p[k]));
        u_[k] = static_cast<T>(factor * static_cast<double>(u_[k]));
      }
    });
  }

  // The preconditioned CG for G p = h - d on the elastic set (p held elsewhere), from p with its values off
  // the plastic set times `scale` (the load's rescaling; u_ then scales with p when current, which the
  // caller makes sure only without plastic nodes); under load control sum p fixed (the direction has zero sum
  // on the set, which also leaves d free), under separation control d = separation_ and the sum free; u_ ends
  // as G p. Stops when the residual's L2 norm has fallen by `reduction` (0: never on that count), or when its
  // largest value is at most `absolute` and the last step's relative change of the pressure at most
  // `step_change`, or after `budget` iterations. Returns the iterations.
  //
  // The residual is the gap less its mean on the set under load control (the mean is the flat's unknown
  // height), the gap d + u - h under separation control. The preconditioner is z = E^T F E r, E the extension
  // of r off the set (kExtensionRadius above): Er = r on the set and, off it, the window sum of r on the set
  // times the node's weight (1 / the window's count of set nodes, floored). F alone on r with zeros off the
  // set bounds G's restriction to the set from above, but far too high for a pressure that varies slowly
  // across many small spots: those are the CG's slow modes (scripts/extended_filter_model.py, a numpy model
  // of this CG: the largest eigenvalue of the preconditioned operator on an H = 0.8 surface at 512^2 and
  // 10 % contact is 11.5 without E and 3.2 with a window of radius 6; the smallest is 1 with or without).
  // An iteration is two convolutions (bem/convolution.hpp), the window sums riding in their producers
  // (bem/box_sum.hpp, WindowRows: each thread's rows come in order):
  //   filter:    producing Er (off the set the weighted window sums of r on the set) | consuming F E r, in
  //              single precision: kept on the set, times the weight off it, and the sum on the set that
  //              E^T will leave (sum_after_transpose); <r, z> is <Er, F Er>, the transform's own product;
  //   operator:  producing the direction t from z on the set plus the window sums of z off it (E^T) | the
  //              step length from <t, G t>, the transform's product, before any row comes back | consuming
  //              G t: p, u and r stepped, and the sums of the next residual.
  // Sums are per thread and combined in thread order: deterministic for a fixed thread count.
  Index cg_on_set(std::vector<T>& p, double scale, double reduction, double absolute, double step_change,
                  Index budget, const std::function<void()>& between) {
    const std::uint8_t* const in = in_.data();
    const std::uint8_t* const plastic = plastic_.data();
    const T* const h = h_.data();
    T* const z = z_.data();
    T* const t = t_.data();
    T* const u = u_.data();
    T* const pp = p.data();
    const Index nx = grid_.nx;
    using Producer = typename Convolution<T>::Producer;
    using Consumer = typename Convolution<T>::Consumer;
    using ProductHook = typename Convolution<T>::ProductHook;
    using FilterProducer = Convolution<float>::Producer;
    using FilterConsumer = Convolution<float>::Consumer;
    // The set's size and the sum of u - h on it, counted in the pass that makes the load's rescaling: p
    // times `scale` off the plastic set, and u = G p with it when current; else u = G p made afresh, the
    // rescaling on p's way into the transform and the count on u's way out. From here u is kept by the
    // steps (u -= tau G t). The start's mean from a pass of its own, before the residual's: sums of squares
    // about a far-off mean would lose the residual to cancellation (u - h is about -d on the set, the
    // residual many decades smaller).
    auto rescaled = [&](std::size_t k) {
      if (scale != 1 && !plastic[k]) pp[k] = static_cast<T>(scale * static_cast<double>(pp[k]));
    };
    // Also the plastic nodes' sum of p (H each): off both sets p = 0, so the sum of |p| the CG's relative
    // change needs is that of the elastic set, where p moves, and this constant.
    auto counted = [&](std::size_t k, Sums& part) {
      if (in[k]) {
        part.a += static_cast<double>(u[k]) - static_cast<double>(h[k]);
        part.c += 1;
      }
      part.g += plastic[k] ? static_cast<double>(pp[k]) : 0.0;
    };
    Sums count;
    if (displacement_current_) {
      count = over_points([&](std::size_t begin, std::size_t end, Sums& part) {
        for (std::size_t k = begin; k < end; ++k) {
          rescaled(k);
          if (scale != 1) u[k] = static_cast<T>(scale * static_cast<double>(u[k]));  // no plastic nodes
          counted(k, part);
        }
      });
    } else {
      count = fresh_displacement(p, rescaled, counted);
    }
    set_size_ = count.c;
    set_mean_ = 0;
    if (set_size_ == 0) return 0;
    // The residual is r - c on the set: r stepped by the CG (r -= tau G t), c the mean those steps add to it
    // under load control (0 under separation control). Stepped, not formed from u - h at each step: in single
    // precision u - h carries the round-off of u (about 1e-14 m on a micrometre surface), and at 2048^2 the
    // residual's norm never fell below that floor (the solve ran on for minutes). Of x = r - c on the set:
    // its sum, its sum of squares, its largest and its smallest value (as the largest of -x).
    T* const r = r_.data();
    double c = 0;
    auto residual_sums = [&](Sums& part, std::size_t k, double shift) {  // shift: c, as a local copy
      const double x = static_cast<double>(r[k]) - shift;
      part.a += x;
      part.b += x * x;
      part.e = std::max(part.e, x);
      part.f = std::max(part.f, -x);
    };
    const Index radius = extension_radius();
    float* const weight = extension_weight_.data();
    // The extension's weights of this set, made before the first iteration (none when the start is
    // already within the stopping test).
    auto make_weights = [&] {
      const double floor = kExtensionFloor * static_cast<double>((2 * radius + 1) * (2 * radius + 1));
      auto weight_of = [&](std::size_t k, double count) {
        return in[k] ? 0.0f : static_cast<float>(1 / std::max(count, floor));
      };
      if (weights_current_) {
        update_weights(radius, weight_of);
      } else {
        box_sum(
            grid_.nx, grid_.ny, radius, grid_.periodic,
            [&](Index y, double* values) {
              const std::uint8_t* const in_row = in + y * nx;
              for (Index x = 0; x < nx; ++x)
                values[x] = in_row[x] ? 1.0 : 0.0;
            },
            [&](Index y, const double* sums, int) {
              for (Index x = 0; x < nx; ++x) {
                const std::size_t k = static_cast<std::size_t>(y * nx + x);
                window_count_[k] = static_cast<std::uint16_t>(sums[x]);
                weight[k] = weight_of(k, sums[x]);
              }
            },
            window_rows_, team());
      }
      weights_current_ = true;
      pending_flips_.clear();
    };
    // r = u - h less its mean on the set (load control), u - h + d (separation control).
    const double start_shift = load_control_ ? count.a / set_size_ : -separation_;
    const Sums start = over_points([&, start_shift](std::size_t begin, std::size_t end, Sums& part) {
      part.e = part.f = -std::numeric_limits<double>::infinity();
      for (std::size_t k = begin; k < end; ++k)  // (r off the set is the extension's, written before use)
        if (in[k]) {
          r[k] = static_cast<T>(static_cast<double>(u[k]) - static_cast<double>(h[k]) - start_shift);
          residual_sums(part, k, 0.0);
        }
    });
    double norm = 0, largest = 0;
    // c moved to the mean of x (load control), and the residual's norm and largest value from the sums.
    auto settle = [&](const Sums& s) {
      const double shift = load_control_ ? s.a / set_size_ : 0.0;
      c += shift;
      norm = std::sqrt(std::max(s.b - 2 * shift * s.a + set_size_ * shift * shift, 0.0));
      largest = std::max(s.e - shift, s.f + shift);
    };
    settle(start);
    const double r0 = norm;
    auto clear = [&] {
      for (Sums& s : sums_)
        s = Sums{};
    };
    // Filter: r in; z = its image kept on the set out, with its sum.
    T shift_c = 0;
    double to_filter = 1, from_filter = 1;  // powers of two: the residual's scale into the filter and back
    // E's inputs: the residual on the set, 0 off it.
    auto extension_inputs = [&](Index y, double* values) {
      const std::uint8_t* const in_row = in + y * nx;
      const T* const r_row = r + y * nx;
      const T cc = shift_c;
      for (Index x = 0; x < nx; ++x) {
        const T rv = r_row[x];
        values[x] = static_cast<double>((in_row[x] ? rv : cc) - cc);
      }
    };
    auto residual_in = [&](Index first, Index rows, float* buffer, Index ld, int thread) {
      const T cc = shift_c;
      const double scale_in = to_filter;
      WindowRows& window = window_rows_[static_cast<std::size_t>(thread)];
      for (Index y = 0; y < rows; ++y) {
        const Index i0 = (first + y) * nx;
        float* const out = buffer + y * ld;
        if (radius > 0) {  // off the set: the window sum of r on the set x weight
          const double* const sums = window.sums(first + y, extension_inputs);
          for (Index x = 0; x < nx; ++x) {
            const double on_set = static_cast<double>(r[i0 + x] - cc);
            const double off_set = sums[x] * static_cast<double>(weight[i0 + x]);
            out[x] = static_cast<float>((in[i0 + x] ? on_set : off_set) * scale_in);
          }
        } else {
          for (Index x = 0; x < nx; ++x) {
            const double on_set = static_cast<double>(r[i0 + x] - cc);
            out[x] = static_cast<float>((in[i0 + x] ? on_set : 0.0) * scale_in);
          }
        }
      }
    };
    auto filtered_out = [&](Index first, Index rows, const float* buffer, Index ld, int thread) {
      const double scale_out = from_filter;
      double z_sum = 0;
      for (Index y = 0; y < rows; ++y) {
        const Index i0 = (first + y) * nx;
        for (Index x = 0; x < nx; ++x) {
          const T filtered = static_cast<T>(static_cast<double>(buffer[y * ld + x]) * scale_out);
          const T w = static_cast<T>(weight[i0 + x]);
          z[i0 + x] = in[i0 + x] ? filtered : (radius > 0 ? filtered * w : T(0));
        }
        z_sum += radius > 0 ? sum_after_transpose(in + i0, z + i0, window_count_.data() + i0, nx)
                            : sum_on_set(in + i0, z + i0, nx);
      }
      sums_[static_cast<std::size_t>(thread)].a += z_sum;
    };
    // Operator: the direction t = (z - zbar) + beta t on the set in; the step tau = <r, z>/<t, G t> once the
    // spectrum is multiplied; G t out: p -= tau t, u -= tau G t, and the sums of the new residual and of the
    // pressure's change.
    T zbar = 0, beta = 0, tau = 0;
    double rz = 0, t_gt = 0;
    // E^T's inputs: z off the set (already times its weight), 0 on it.
    auto transpose_inputs = [&](Index y, double* values) {
      const std::uint8_t* const in_row = in + y * nx;
      const T* const z_row = z + y * nx;
      for (Index x = 0; x < nx; ++x) {
        const double off_set = static_cast<double>(z_row[x]);
        values[x] = in_row[x] ? 0.0 : off_set;
      }
    };
    auto direction_in = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
      const T zb = zbar, b = beta;
      WindowRows& window = window_rows_[static_cast<std::size_t>(thread)];
      for (Index y = 0; y < rows; ++y) {
        const Index i0 = (first + y) * nx;
        // z on the set gains the window sums of z off it (E^T)
        const double* const sums = radius > 0 ? window.sums(first + y, transpose_inputs) : nullptr;
        for (Index x = 0; x < nx; ++x)  // t is read and written on the set only (b = 0 at a start)
          if (in[i0 + x]) {
            const T zk = sums ? static_cast<T>(static_cast<double>(z[i0 + x]) + sums[x]) : z[i0 + x];
            const T tv = (zk - zb) + b * t[i0 + x];
            t[i0 + x] = tv;
            buffer[y * ld + x] = tv;
          } else {
            buffer[y * ld + x] = T(0);
          }
      }
    };
    auto step_length = [&](double product) {
      t_gt = product;
      tau = static_cast<T>(t_gt > 0 ? rz / t_gt : 0.0);
    };
    auto stepped_out = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
      Sums s;  // local: see over_points
      s.e = s.f = -std::numeric_limits<double>::infinity();
      const T step = tau;
      const double shift = c;
      for (Index y = 0; y < rows; ++y) {
        const Index i0 = (first + y) * nx;
        double moved = 0, sum = 0;
        for (Index x = 0; x < nx; ++x) {
          const std::size_t k = static_cast<std::size_t>(i0 + x);
          const T w = buffer[y * ld + x];
          u[k] -= step * w;
          if (in[k]) {  // t = 0 off the set: p moves on it only
            const T change = step * t[k];
            moved += std::abs(static_cast<double>(change));
            pp[k] -= change;
            sum += std::abs(static_cast<double>(pp[k]));
            r[k] -= step * w;
            residual_sums(s, k, shift);
          }
        }
        s.c += moved;
        s.d += sum;
      }
      sums_[static_cast<std::size_t>(thread)].add(s);
    };
    double rz_old = 0;
    Index iterations = 0;
    last_step_change_ = 0;  // no step yet: the pressure has not moved
    for (; iterations < budget; ++iterations) {
      // While the set still changes (reduction > 0) a gap within the threshold everywhere on the set also
      // ends the solve: what is left to reduce is below what the update and the convergence test resolve.
      const bool within = largest <= absolute && (reduction > 0 || last_step_change_ <= step_change);
      if (within || norm <= reduction * r0 || norm == 0) break;
      if (between) between();
      if (iterations == 0 && radius > 0) make_weights();
      clear();
      shift_c = static_cast<T>(c);
      // Into the filter scaled by a power of two to about 1 (float's range: a residual of 1e-20 m squared
      // in the product would underflow), out scaled back: exact apart from float's rounding.
      to_filter = std::ldexp(1.0, -std::ilogb(largest));
      from_filter = std::ldexp(1.0, std::ilogb(largest));
      restart_windows();
      rz = filter_->apply(FilterProducer(residual_in), FilterConsumer(filtered_out), {}, true) * from_filter *
           from_filter;  // <r, z>
      zbar = static_cast<T>(load_control_ ? combined().a / set_size_ : 0.0);
      if (!(rz > 0)) break;  // no descent left (a set of one node, or round-off)
      beta = static_cast<T>(rz_old > 0 ? rz / rz_old : 0.0);
      rz_old = rz;
      clear();
      for (Sums& s : sums_)
        s.e = s.f = -std::numeric_limits<double>::infinity();
      restart_windows();
      operator_->apply(Producer(direction_in), Consumer(stepped_out), {}, true, ProductHook(step_length));
      displacement_fresh_ = false;  // u stepped
      if (!(t_gt > 0)) break;       // nothing moved: tau was 0
      const Sums f = combined();
      const double pressure_sum = f.d + count.g;  // sum |p|: the elastic set's and the plastic nodes'
      last_step_change_ = pressure_sum > 0 ? f.c / pressure_sum : 0;
      settle(f);
    }
    set_mean_ = start_shift + c;  // u - h = r + start_shift on the set, r stepped as u is
    return iterations;
  }

  // The nested start: the same problem on the surface averaged over 2 x 2 blocks solved to
  // kCoarseTolerance (itself nested), its pressure interpolated. Returns the coarse level's outcome (no
  // iterations when the grid is too small or odd: then the start is the uniform pressure under load control,
  // and under separation control the penetration pressed in by the stiffness of one pixel, as PK's).
  ActiveSetOutcome nested_start(const ActiveSetProblem& problem, std::vector<T>& p,
                                const std::function<void()>& between) {
    if (!coarse_) {
      p.assign(n_, T(1));
      if (!problem.load_control) {
        const double stiffness = 1 / operator_->self_response();
        for (std::size_t k = 0; k < n_; ++k)
          p[k] = static_cast<T>(std::min(
              std::max(static_cast<double>(h_[k]) - problem.separation, 0.0) * stiffness, problem.hardness));
      }
      return {};
    }
    std::vector<T> coarse_pressure;
    const ActiveSetOutcome o =
        coarse_->solve(problem, kCoarseTolerance, 100000, false, coarse_pressure, between);
    p = interpolate_up(coarse_pressure, grid_.nx / 2, grid_.ny / 2, grid_.periodic, cap_, team());
    return o;
  }

  // The next coarser level (null when the grid is too small or odd): the surface averaged over 2 x 2 blocks.
  void make_coarse_level() {
    const Index nx = grid_.nx, ny = grid_.ny;
    if (nx % 2 != 0 || ny % 2 != 0 || nx / 2 < kCoarsest || ny / 2 < kCoarsest) return;
    Grid coarse_grid = grid_;
    coarse_grid.nx = nx / 2;
    coarse_grid.ny = ny / 2;
    std::vector<T> coarse_heights(static_cast<std::size_t>(coarse_grid.points()));
    auto at = [&](Index y, Index x) { return static_cast<double>(h_[static_cast<std::size_t>(y * nx + x)]); };
    for (Index y = 0; y < coarse_grid.ny; ++y)
      for (Index x = 0; x < coarse_grid.nx; ++x)
        coarse_heights[static_cast<std::size_t>(y * coarse_grid.nx + x)] =
            static_cast<T>(0.25 * (at(2 * y, 2 * x) + at(2 * y, 2 * x + 1) + at(2 * y + 1, 2 * x) +
                                   at(2 * y + 1, 2 * x + 1)));
    coarse_ = std::make_unique<ActiveSet<T>>(coarse_grid, std::move(coarse_heights), modulus_, threads_);
  }

  Grid grid_;
  std::vector<T> h_;
  Real modulus_;
  int threads_;
  std::unique_ptr<Convolution<T>> operator_;
  // The preconditioner's filter in single precision whatever T (cg_on_set).
  std::unique_ptr<Convolution<float>> filter_;
  std::size_t n_;
  std::vector<T> u_, r_, z_, t_;  // G p, the CG's residual, the filtered residual, the CG's direction
  // Off the set: 1 / the window's count of set nodes (floored). In single precision whatever T: E and E^T
  // read the same weights, so the preconditioner stays symmetric, and each iteration reads them twice
  // (surface A at 1 % contact: the same iterations in the 30 cases, 2 to 4 % less time at 1024^2 and
  // 2048^2).
  std::vector<float> extension_weight_;
  // The window sums of the extended filter, one per thread of the team (bem/box_sum.hpp).
  std::vector<WindowRows> window_rows_;
  std::vector<std::uint8_t> in_;       // the elastic contact set
  std::vector<std::uint8_t> plastic_;  // the plastic set, p = H (none without a hardness)
  bool load_control_ = true;
  double separation_ = 0;                       // the flat's height under separation control
  T cap_ = std::numeric_limits<T>::infinity();  // the hardness
  double height_range_ = 1, highest_ = 0, gap_round_off_ = 0;
  double last_step_change_ = 0;        // sum |tau t| / sum |p| of the last CG iteration
  bool displacement_current_ = false;  // u_ is G p for the current p (fresh, or kept by the CG's steps)
  bool displacement_fresh_ = false;    // ... and made by an application of G, no CG step since
  std::vector<Sums> sums_;
  struct Change {
    std::size_t node = 0;
    double dp = 0;
  };
  std::vector<std::array<Change, kFewChanges>> changes_;  // per thread, recorded by keep_to_sets
  std::vector<T> response_;                  // G e_0: the displacement of a unit pressure at node 0
  std::vector<std::uint16_t> window_count_;  // per node: the set nodes in its window (with the weights)
  bool weights_current_ = false;             // the weights are those of the set before pending_flips_
  std::vector<std::vector<Flip>> flips_;     // per thread: the last set update's flips
  std::vector<Flip> pending_flips_;          // the flips since the weights were made
  double set_size_ = 1;                      // nodes in the set
  double set_mean_ = 0;                      // the mean of u - h on the set at the CG's end (load control)
  double contact_fraction_ = 0;              // of the nodes, in contact (p > 0) in the last solution
  std::unique_ptr<ActiveSet<T>> coarse_;     // the next coarser level of the nested start, once made
};

}  // namespace

template <class T>
struct ActiveSetSolver<T>::Impl {
  ActiveSet<T> solver;
};

template <class T>
ActiveSetSolver<T>::ActiveSetSolver(const Grid& grid, std::vector<T> heights, Real modulus, int threads)
    : impl_(std::make_unique<Impl>(Impl{ActiveSet<T>(grid, std::move(heights), modulus, threads)})) {}

template <class T>
ActiveSetSolver<T>::~ActiveSetSolver() = default;

template <class T>
ActiveSetOutcome ActiveSetSolver<T>::solve(const ActiveSetProblem& problem, double tolerance,
                                           Index max_iterations, bool warm, std::vector<T>& pressure,
                                           std::vector<T>& displacement_minus_heights,
                                           const std::function<void()>& between) {
  const ActiveSetOutcome outcome =
      impl_->solver.solve(problem, tolerance, max_iterations, warm, pressure, between);
  impl_->solver.displacement_minus_heights(displacement_minus_heights);
  return outcome;
}

template class ActiveSetSolver<double>;
template class ActiveSetSolver<float>;

}  // namespace contactbench
