#include "contactbench/bem/solvers/polonsky_keer_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/bem/solvers/polonsky_keer_step.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

using cg::Moments;
using cg::Partial;

template <class T>
PolonskyKeerSolver<T>::PolonskyKeerSolver(const Surface& centred, Real modulus, int threads)
    : PressureState<T>(centred, threads),
      convolution_(make_half_space_convolution<T>(centred.grid(), modulus, threads)),
      t_(static_cast<std::size_t>(this->n_)),
      partial_(static_cast<std::size_t>(convolution_->threads())) {
  this->q_[1].resize(static_cast<std::size_t>(this->n_));  // the iteration's second pressure (PressureState)
}

template <class T>
SolveOutcome PolonskyKeerSolver<T>::solve_load(double mean_pressure, double, double tolerance,
                                               Index max_iterations, bool extrapolate) {
  this->begin_load(mean_pressure, extrapolate);
  if (!this->warm_) {  // the uniform pressure
    std::fill(this->q_[this->cur_].begin(), this->q_[this->cur_].end(), T(1));
    this->s_[this->cur_] = mean_pressure;
  }
  this->hardness_ = std::numeric_limits<double>::infinity();
  const double total = mean_pressure * static_cast<double>(this->n_);
  const SolveOutcome outcome = iterate<true, false>(total, tolerance, max_iterations);
  this->end_load(mean_pressure);
  return outcome;
}

template <class T>
SolveOutcome PolonskyKeerSolver<T>::solve_separation(double separation, double hardness, double tolerance,
                                                     Index max_iterations) {
  this->end_load_series();
  this->separation_ = separation;
  this->hardness_ = this->stored(hardness);
  if (!this->warm_) {
    // The surface's penetration of the flat, pressed in by the stiffness of a lone pixel (capped).
    const double stiffness = 1 / convolution_->self_response();
    for (Index i = 0; i < this->n_; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      const double penetration = std::max(static_cast<double>(this->h_[k]) - separation, 0.0);
      this->q_[this->cur_][k] = static_cast<T>(std::min(penetration * stiffness, hardness));
    }
    this->s_[this->cur_] = 1;
  }
  const SolveOutcome outcome = std::isfinite(hardness) ? iterate<false, true>(0, tolerance, max_iterations)
                                                       : iterate<false, false>(0, tolerance, max_iterations);
  this->warm_ = true;
  return outcome;
}

template <class T>
void PolonskyKeerSolver<T>::impose_load(double mean_pressure, double given_hardness) {
  // One pass to scale the elastic pressures, one application of G for the gap (a load-control gap pass).
  const double hardness = this->stored(given_hardness);
  std::vector<T>& q = this->q_[this->cur_];
  const double s = this->s_[this->cur_];
  double elastic = 0, plastic = 0;
  for (const T v : q) {
    const double p = s * static_cast<double>(v);
    if (p >= hardness)
      plastic += hardness;
    else
      elastic += p;
  }
  const double total = mean_pressure * static_cast<double>(this->n_);
  const double factor = elastic > 0 ? (total - plastic) / elastic : 1.0;
  for (T& v : q) {
    const double p = s * static_cast<double>(v);
    v = static_cast<T>(p >= hardness ? hardness : std::min(factor * p, hardness));
  }
  this->s_[this->cur_] = 1;
  this->hardness_ = hardness;
  this->separation_ = 0;
  // The gap of the result, with the flat from the mean gap on the elastic set.
  const Index nx = this->grid_.nx;
  const T* const q_data = q.data();
  const T* const h = this->h_.data();
  T* const g = this->g_.data();
  const T h_cap = static_cast<T>(hardness);
  auto copy_in = [&](Index first, Index rows, T* buffer, Index ld, int) {
    for (Index r = 0; r < rows; ++r)
      std::copy_n(q_data + (first + r) * nx, nx, buffer + r * ld);
  };
  auto gap = [&](Index first, Index rows, const T* u, Index ld, int thread) {
    Partial& part = partial_[static_cast<std::size_t>(thread)];
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      cg::gap_rows<true, true>(part, q_data + i0, q_data + i0, u + r * ld, h + i0, g + i0, nx, T(1), T(1),
                               T(0), h_cap);
    }
  };
  clear_partials();
  convolution_->apply(Producer(copy_in), Consumer(gap));
  const Moments moments = cg::combine_moments<true>(partial_);
  this->separation_ = -moments.g_mean;
  this->gap_offset_ = this->separation_;
  this->last_sum_ = moments.sum;
}

// The loop. kLoad: the load `total` (sum of p) is imposed: the gap is made zero-mean on the elastic set,
// which fixes the flat, and p rescaled to the load. Else the flat's height is separation_: no mean taken
// out, no rescaling. kHard: pressures capped at hardness_ (separation control only: under load control
// the cap is met by a search on the flat's height, bem/solvers/hardness_search.hpp).
template <class T>
template <bool kLoad, bool kHard>
SolveOutcome PolonskyKeerSolver<T>::iterate(double total, double tolerance, Index max_iterations) {
  static_assert(!(kLoad && kHard));
  const Index nx = this->grid_.nx;
  const T* const h = this->h_.data();
  T* const g = this->g_.data();
  T* const t = t_.data();
  const T hardness = kHard ? static_cast<T>(this->hardness_) : std::numeric_limits<T>::infinity();
  const T offset = kLoad ? T(0) : static_cast<T>(this->separation_);  // g = offset - h + u

  // Consuming u = G q (unscaled): the new pressure s q, its change from s_old q_old, the gap, its moments.
  const T* q_new = nullptr;
  const T* q_old = nullptr;
  T s_new = 0, s_old = 0;
  auto gap = [&](Index first, Index rows, const T* u, Index ld, int thread) {
    Partial& part = partial_[static_cast<std::size_t>(thread)];
    const T sn = s_new, so = s_old;
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      cg::gap_rows<kLoad, kHard>(part, q_new + i0, q_old + i0, u + r * ld, h + i0, g + i0, nx, sn, so, offset,
                                 hardness);
    }
  };
  // Producing t = g - gbar + beta t on the elastic set (0 elsewhere).
  Pass pass;
  auto direction = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
    Partial& part = partial_[static_cast<std::size_t>(thread)];
    const T sc = pass.s, gb = pass.gbar, b = pass.beta;
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      cg::direction_row<kHard>(part, pass.q + i0, g + i0, t + i0, buffer + r * ld, nx, sc, gb, b, hardness);
    }
  };
  // The preconditioned direction serves load control only. Under separation control (and so with a
  // hardness, which is met by separation control) the residual is not the gap less its mean on the set:
  // preconditioned that way the iteration stopped after 6 iterations on surface A with a residual of 5 % of
  // the height range and the load 100 x off, yet "converged". Those solves iterate as plain Polonsky-Keer
  // (python/tests/test_bem.py checks that separation control gives the load back; active_set solves them
  // itself).
  const bool preconditioned = preconditions() && kLoad;
  // Consuming r = G t: its sum on the elastic set (its mean is taken out: PK's step for the unknown flat).
  auto response = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
    Partial& part = partial_[static_cast<std::size_t>(thread)];
    for (Index r = 0; r < rows; ++r)
      cg::response_row(part, pass.q + (first + r) * nx, buffer + r * ld, nx);
  };
  // Producing the update q = max(p - tau t, 0) (capped at H), entering and leaving nodes moved by
  // update_row's rule.
  T tau = 0, tau_enter = 0;
  T* q_next = nullptr;
  auto update = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
    Partial& part = partial_[static_cast<std::size_t>(thread)];
    const T sc = pass.s, step = tau, enter = tau_enter, gb = pass.gbar;
    for (Index r = 0; r < rows; ++r) {
      const Index i0 = (first + r) * nx;
      cg::update_row<kHard>(part, pass.q + i0, t + i0, g + i0, q_next + i0, buffer + r * ld, nx, sc, step,
                            enter, gb, hardness);
    }
  };
  auto copy_in = [&](Index first, Index rows, T* buffer, Index ld, int) {
    for (Index r = 0; r < rows; ++r)
      std::copy_n(q_new + (first + r) * nx, nx, buffer + r * ld);
  };
  // Under load control the new pressure is rescaled to the load: its sum is known once every row is
  // produced, before any is consumed.
  auto rescale = [&] {
    double sum = 0;
    for (const Partial& part : partial_)
      sum += part.q_sum;
    s_new = kLoad ? static_cast<T>(sum > 0 ? total / sum : 0.0) : T(1);
  };

  // The first gap, of the starting pressure.
  int& cur = this->cur_;
  q_new = q_old = this->q_[cur].data();
  s_new = s_old = static_cast<T>(this->s_[cur]);
  clear_partials();
  convolution_->apply(Producer(copy_in), Consumer(gap));
  Moments moments = cg::combine_moments<kLoad>(partial_);

  double g_norm_old = 1, delta = 0, change = 0;  // delta = 0: the first step is steepest descent
  double rz_old = 1;                             // preconditioned: <r, z> of the last direction
  double entered = 0;                            // nodes that entered (or left) the set in the last update
  PolonskyKeerStep step;                         // the criterion, the damping, the step lengths
  SolveOutcome outcome;
  Index iteration = 0;
  for (;;) {
    if (iteration > 0) {
      change = PolonskyKeerStep::relative_change(moments.change, moments.sum);
      if (PolonskyKeerStep::converged(change, tolerance, preconditioned, entered)) {
        outcome.converged = true;
        break;
      }
      step.observe(change);
    }
    if (iteration == max_iterations) break;
    if (this->between_iterations_) {
      try {
        this->between_iterations_();
      } catch (...) {
        this->forget();  // the fields are mid-iteration: nothing to warm-start from
        throw;
      }
    }
    if (kLoad && moments.elastic == 0) throw Error("Polonsky-Keer: the contact set became empty");
    // The gap made zero-mean on the elastic set (load control), the conjugate direction there (PK eq. 11),
    // restarted after the set grew (delta = 0).
    pass.q = this->q_[cur].data();
    pass.s = static_cast<T>(this->s_[cur]);
    pass.gbar = static_cast<T>(moments.g_mean);
    if (preconditioned) {
      // z = the filtered residual on the elastic set, zbar its mean there (load control); Fletcher-Reeves'
      // beta of the preconditioned CG, <r, z - zbar> over the last one (r has zero mean on the set).
      const FilterSums f = filter_residual(pass);
      const double z_mean = kLoad ? f.z_sum / moments.elastic : 0.0;
      pass.zbar = static_cast<T>(z_mean);
      const double rz_centred = f.rz - z_mean * f.r_sum;
      pass.beta = static_cast<T>(delta > 0 && rz_old > 0 ? rz_centred / rz_old : 0.0);
      rz_old = rz_centred;
    } else {
      pass.beta = static_cast<T>(delta > 0 && g_norm_old > 0 ? moments.g_norm / g_norm_old : 0.0);
      g_norm_old = moments.g_norm;
    }
    clear_partials();
    const double t_r =
        preconditioned
            ? preconditioned_direction(pass, Consumer(response))
            : convolution_->apply(Producer(direction), kLoad ? Consumer(response) : Consumer(), Hook(), true);
    double gt = 0, t_sum = 0, r_sum = 0, tt = 0;
    for (const Partial& part : partial_) {
      gt += part.gt;
      t_sum += part.t_sum;
      r_sum += part.r_sum;
      tt += part.tt;
    }
    // t . (r - rbar) on the elastic set; t is zero elsewhere, so t . r is the operator's own product.
    const double tr = kLoad ? t_r - r_sum / moments.elastic * t_sum : t_r;
    const PolonskyKeerStep::Lengths lengths =
        step.lengths(gt, tr, tt, convolution_->self_response(), preconditioned);
    tau = static_cast<T>(lengths.tau);
    tau_enter = static_cast<T>(lengths.enter);

    // The update, and with it the next gap.
    const int next = 1 - cur;
    q_next = this->q_[next].data();
    q_new = q_next;
    q_old = pass.q;
    s_old = pass.s;
    clear_partials();
    convolution_->apply(Producer(update), Consumer(gap), Hook(rescale));
    cur = next;
    this->s_[cur] = static_cast<double>(s_new);
    entered = 0;
    for (const Partial& part : partial_)
      entered += part.entered;
    delta = entered > 0 ? 0 : 1;
    moments = cg::combine_moments<kLoad>(partial_);
    ++iteration;
  }
  outcome.iterations = iteration;
  outcome.change = change;
  this->last_sum_ = moments.sum;
  if constexpr (kLoad) {
    this->separation_ = -moments.g_mean;    // the flat, from the mean gap on the contact set
    this->gap_offset_ = this->separation_;  // g holds u - h: the gap is g + d
  } else {
    this->gap_offset_ = 0;  // g holds d - h + u already
  }
  return outcome;
}

template class PolonskyKeerSolver<double>;
template class PolonskyKeerSolver<float>;

SolverEntry polonsky_keer_entry() {
  return {
      .kind = SolverKind::polonsky_keer,
      .name = "polonsky_keer",
      .description = "Polonsky & Keer's constrained conjugate gradient: the direction from the gap itself",
      .separation_control = true,
      .hardness = false,
      .single_precision = true,
      // Warm, the last solution scaled: on the benchmark's 10-load curves (contact 1 % to 30 %,
      // bench/bench_load_path.cpp) 0.62 to 0.75 of the cold solves' iterations at 256^2 and 512^2, the
      // extrapolation 0.74 to 0.91 (docs/solvers.md "Starts").
      .load_path = [](const Grid&, bool) { return LoadPathStart::scaled; },
      .make = [](const Surface& centred, Real modulus, int threads,
                 bool single_precision) -> std::unique_ptr<ContactSolver> {
        if (single_precision) return std::make_unique<PolonskyKeerSolver<float>>(centred, modulus, threads);
        return std::make_unique<PolonskyKeerSolver<double>>(centred, modulus, threads);
      }};
}

}  // namespace contactbench
