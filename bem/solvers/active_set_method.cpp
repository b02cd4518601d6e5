#include "contactbench/bem/solvers/active_set_method.hpp"

#include "contactbench/bem/fourier_preconditioner.hpp"
#include "contactbench/bem/half_space.hpp"

namespace contactbench {

using namespace active_set_tuning;

template <class T>
ActiveSet<T>::ActiveSet(const Grid& grid, std::vector<T> heights, Real modulus, int threads, FftRigor rigor)
    : grid_(grid),
      h_(std::move(heights)),
      modulus_(modulus),
      threads_(threads),
      operator_(make_half_space_convolution<T>(grid, modulus, threads, rigor)),
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
  // r and t are read off the set (r's value discarded, t times beta = 0 at a start): zeros, written by the
  // threads whose static split of the points later uses them (their pages' first touch on those threads).
  over_points([&](std::size_t begin, std::size_t end, Sums&) {
    std::fill(r_.begin() + static_cast<std::ptrdiff_t>(begin), r_.begin() + static_cast<std::ptrdiff_t>(end),
              T(0));
    std::fill(t_.begin() + static_cast<std::ptrdiff_t>(begin), t_.begin() + static_cast<std::ptrdiff_t>(end),
              T(0));
  });
  measure_heights();
  make_coarse_level();  // the whole hierarchy, with its FFT plans, made once
  for (int thread = 0; thread < team(); ++thread)
    window_rows_.emplace_back(grid_.nx, grid_.ny, extension_radius(), grid_.periodic);
  changes_.resize(sums_.size());
  flips_.resize(sums_.size());
  window_count_.resize(n_);
  // response_ (G's column of node 0) is made by add_columns on its first use: a solve whose set updates
  // never change a few pressures only (and a coarse level often) never needs it, and it costs an
  // application of G (issue 42).
}

template <class T>
void ActiveSet<T>::measure_heights() {
  const auto [low, high] = std::minmax_element(h_.begin(), h_.end());
  highest_ = static_cast<double>(*high);
  // The round-off of a gap d - h + u: a few epsilons of T of the largest height.
  gap_round_off_ = 8 * static_cast<double>(std::numeric_limits<T>::epsilon()) *
                   std::max(std::abs(static_cast<double>(*low)), std::abs(highest_));
  height_range_ = highest_ - static_cast<double>(*low);
  if (!(height_range_ > 0)) height_range_ = 1;  // a flat surface: relative to 1 m, as ContactSolution
}

template <class T>
void ActiveSet<T>::set_heights(const std::vector<T>& heights) {
  h_ = heights;
  measure_heights();
  displacement_current_ = displacement_fresh_ = false;
  weights_current_ = false;
  if (coarse_) coarse_->set_heights(coarse_heights(coarse_->grid_));
}

template <class T>
ActiveSetOutcome ActiveSet<T>::solve(const ActiveSetProblem& problem, double tolerance, Index max_iterations,
                                     bool warm, std::vector<T>& p, const std::function<void()>& between) {
  ActiveSetOutcome outcome;
  load_control_ = problem.load_control;
  separation_ = problem.separation;
  cap_ =
      std::isfinite(problem.hardness) ? static_cast<T>(problem.hardness) : std::numeric_limits<T>::infinity();
  const double total = problem.mean_pressure * static_cast<double>(n_);
  displacement_current_ = displacement_fresh_ = false;
  weights_current_ = false;  // the starts below make new sets
  if (!warm) {
    const ActiveSetOutcome coarse = nested_start(problem, p, between);
    outcome.coarse_iterations = coarse.iterations;
    outcome.work = coarse.work / 4;  // a coarse level's iteration costs a quarter of a fine one
  }
  double d = 0;  // the flat's height
  Sums kept = start_sets(p, warm, total, d);

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
      } else if (rescales_the_load(scale) && kept.g > 0) {
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
    const Sums update = update_sets(p, d, limit, entry, capping);
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
    if (converged(changed, above_cap, residual, limit, tolerance)) {
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
  finish(p, total, tolerance, d, kept, inner + column_updates, outcome);
  outcome.work += static_cast<double>(outcome.iterations);
  outcome.iterations = std::llround(outcome.work);
  return outcome;
}

// The output: the pressure of the sets the loop ended on (clipped to them, rescaled to the load if it was),
// its gap afresh when u may have drifted from G p, the flat's height and the counts. `steps`: the updates u
// took since it was last made (the CG's steps and the column updates).
template <class T>
void ActiveSet<T>::finish(std::vector<T>& p, double total, double tolerance, double d, const Sums& kept,
                          Index steps, ActiveSetOutcome& outcome) {
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
  const double drift =
      static_cast<double>(steps + 1) * static_cast<double>(std::numeric_limits<T>::epsilon()) * height_range_;
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
}

// G p - h of the last solution.
template <class T>
void ActiveSet<T>::displacement_minus_heights(std::vector<T>& out) {
  out.resize(n_);
  over_points([&](std::size_t begin, std::size_t end, Sums&) {
    for (std::size_t k = begin; k < end; ++k)
      out[k] = u_[k] - h_[k];
  });
}

template ActiveSetOutcome ActiveSet<double>::solve(const ActiveSetProblem& problem, double tolerance,
                                                   Index max_iterations, bool warm, std::vector<double>& p,
                                                   const std::function<void()>& between);
template ActiveSetOutcome ActiveSet<float>::solve(const ActiveSetProblem& problem, double tolerance,
                                                  Index max_iterations, bool warm, std::vector<float>& p,
                                                  const std::function<void()>& between);
template void ActiveSet<double>::finish(std::vector<double>&, double, double, double, const Sums&, Index,
                                        ActiveSetOutcome&);
template void ActiveSet<float>::finish(std::vector<float>&, double, double, double, const Sums&, Index,
                                       ActiveSetOutcome&);
template void ActiveSet<double>::displacement_minus_heights(std::vector<double>& out);
template void ActiveSet<float>::displacement_minus_heights(std::vector<float>& out);

template ActiveSet<double>::ActiveSet(const Grid&, std::vector<double>, Real, int, FftRigor);
template ActiveSet<float>::ActiveSet(const Grid&, std::vector<float>, Real, int, FftRigor);

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

template <class T>
void ActiveSetSolver<T>::set_heights(const std::vector<T>& heights) {
  impl_->solver.set_heights(heights);
}

template class ActiveSetSolver<double>;
template class ActiveSetSolver<float>;

}  // namespace contactbench
