#include "contactbench/bem/polonsky_keer.hpp"

#include <omp.h>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/bem/active_set.hpp"
#include "contactbench/bem/convolution.hpp"
#include "contactbench/bem/fourier_preconditioner.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// The element-wise kernels are compiled twice, for SSE2 (any x86-64) and AVX2, the better one chosen at load
// time (g++'s function multi-versioning): twice the lanes on the machines that have them. No FMA, so both
// round alike; sums over lanes are ordered differently, so results agree between the two to round-off only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CB_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define CB_KERNEL
#endif

// What one thread sums during one pass: one cache line each, combined in thread order after the pass, so
// that for a fixed thread count the sums (and so the iterates) are the same from run to run.
struct alignas(64) Partial {
  double change = 0, sum = 0;            // sum |p - p_old|, sum p
  double elastic = 0, plastic = 0;       // node counts
  double shift = 0, s1 = 0, s2 = 0;      // sum (g - shift), sum (g - shift)^2 over the elastic set
  bool has_shift = false;                // see gap_rows
  double gt = 0, t_sum = 0, r_sum = 0;   // sum g t, sum t, sum r over the elastic set
  double q_sum = 0, entered = 0;         // sum of the new pressure, nodes that entered or left the set
  double rz = 0, z_sum = 0, rr_sum = 0;  // preconditioned: sum r z, sum z, sum r over the elastic set
  double tt = 0;                         // preconditioned: sum t^2
  void clear() { *this = Partial{}; }
};

}  // namespace

// What PolonskyKeer needs of an iteration, whatever its scalar.
class PolonskyKeer::Engine {
 public:
  struct Outcome {
    Index iterations = 0;
    double change = 0;
    bool converged = false;
  };
  virtual ~Engine() = default;
  virtual void forget() = 0;
  void set_between_iterations(std::function<void()> hook) { between_iterations_ = std::move(hook); }
  // Whether a solve would start from a previous solution.
  virtual bool warm() const = 0;
  // The next solve starts from this pressure [Pa] (ny x nx), as from a previous solution.
  virtual void start_from(const HeightMap& pressure) = 0;
  // Load control: mean(p) = mean_pressure, the flat's height found; pressures capped at `hardness` (may be
  // infinite) when caps_load_control(), else elastic (PolonskyKeer::solve then meets the cap by a search on
  // the flat's height, solve_capped). extrapolate: start from the linear extrapolation of the last two
  // load-controlled solutions (when there are two), else from the last one scaled to the new load.
  virtual Outcome solve_load(double mean_pressure, double hardness, double tolerance, Index max_iterations,
                             bool extrapolate) = 0;
  // Whether solve_load meets a hardness itself (active_set's plastic set) rather than solving elastically.
  virtual bool caps_load_control() const = 0;
  // Separation control: the flat at `separation`, the load found; pressures capped at `hardness` (may be
  // infinite).
  virtual Outcome solve_separation(double separation, double hardness, double tolerance,
                                   Index max_iterations) = 0;
  // Rescales the elastic part of the pressure so that the mean is mean_pressure exactly (plastic nodes stay
  // at the hardness), and finds the flat's height and the gap of the result as load control does.
  virtual void impose_load(double mean_pressure, double hardness) = 0;
  // Writes the last solution (pressure, gap, separation, counts, residual); returns the mean pressure.
  virtual double write(ContactSolution& s) const = 0;
  virtual double max_pressure() const = 0;
  // Of the last solve: the flat's height, and the mean pressure (sum p / points).
  virtual double separation() const = 0;
  virtual double mean_pressure() const = 0;

 protected:
  std::function<void()> between_iterations_;  // PolonskyKeerOptions::between_iterations
};

// The iteration of PK's algorithm in scalar T (double, or float for large grids), keeping its state
// (pressure, direction, gap) between solves for warm starts.
//
// The pressure is kept as p = s q: q an array, s a scalar. Under load control the load is imposed by
// rescaling (PK's step), and as the operator is linear, G p = s G q: the rescaling is never a pass over the
// arrays. Two arrays q alternate, so that the change of the pressure in an iteration can be measured while
// the next gap is computed. The sets are read off q: elastic contact where 0 < p < H (the conjugate
// gradient's set), plastic where p = H (with a hardness), out of contact where p = 0. Every element-wise
// step rides inside a convolution (bem/convolution.hpp); one iteration is
//   G t: producing t (direction) | consuming r = G t (its sum on the contact set; load control only)
//   G q: producing q (the update) | consuming u = G q (gap, its moments, the change of the pressure)
// and the apply that finishes an iteration is the one that starts the next: the same count of operator
// applications as PK's loop (two per iteration and one to start), and no other pass over the arrays.
template <class T>
class PolonskyKeerCore final : public PolonskyKeer::Engine {
 public:
  // preconditioned: the solver "preconditioned_cg" (the gap filtered by bem/fourier_preconditioner.hpp
  // before it becomes a direction), else plain Polonsky-Keer.
  PolonskyKeerCore(const Surface& centred, Real modulus, int threads, SolverKind solver)
      : grid_(centred.grid()),
        modulus_(modulus),
        threads_(threads),
        active_set_(solver == SolverKind::active_set),
        convolution_(make_half_space_convolution<T>(centred.grid(), modulus, threads)),
        n_(grid_.points()),
        h_(static_cast<std::size_t>(n_)),
        g_(static_cast<std::size_t>(n_)),
        t_(static_cast<std::size_t>(n_)),
        partial_(static_cast<std::size_t>(convolution_->threads())) {
    if (solver == SolverKind::preconditioned_cg) {
      preconditioner_ = make_fourier_preconditioner<T>(centred.grid(), modulus, threads);
      z_.resize(static_cast<std::size_t>(n_));
      if (preconditioner_->threads() > convolution_->threads())
        partial_.resize(static_cast<std::size_t>(preconditioner_->threads()));
    }
    q_[0].resize(static_cast<std::size_t>(n_));
    q_[1].resize(static_cast<std::size_t>(n_));
    const HeightMap& h = centred.heights();
    for (Index i = 0; i < n_; ++i)
      h_[static_cast<std::size_t>(i)] = static_cast<T>(h.data()[i]);
    height_range_ = h.maxCoeff() - h.minCoeff();
    if (active_set_) active_set_solver_ = std::make_unique<ActiveSetSolver<T>>(grid_, h_, modulus_, threads);
  }

  void forget() override {
    warm_ = false;
    loads_solved_ = 0;
  }

  bool warm() const override { return warm_; }

  void start_from(const HeightMap& pressure) override {
    for (Index i = 0; i < n_; ++i)
      q_[cur_][static_cast<std::size_t>(i)] = static_cast<T>(std::max(pressure.data()[i], 0.0));
    s_[cur_] = 1;
    warm_ = true;
    loads_solved_ = 0;
  }

  bool caps_load_control() const override { return active_set_; }

  // The hardness as T holds it. Plastic nodes store static_cast<T>(H), and every test p >= H (the sets of
  // the iteration, write()'s plastic count and residual) must compare with that value: in float, H = 3.2967e9
  // Pa rounds down, and compared with the double H the plastic nodes counted as elastic, so a capped solve
  // reported no plastic node, a residual of 0.24 of the height range and "not converged".
  static double stored(double hardness) {
    return std::isfinite(hardness) ? static_cast<double>(static_cast<T>(hardness)) : hardness;
  }

  Outcome solve_load(double mean_pressure, double hardness, double tolerance, Index max_iterations,
                     bool extrapolate) override {
    const double total = mean_pressure * static_cast<double>(n_);
    const bool two_behind = extrapolate && warm_ && loads_solved_ >= 2 && last_load_ != previous_load_;
    if (extrapolate && warm_ && loads_solved_ >= 1) {
      // p = p_last + w (p_last - p_before), w = (P - P_last)/(P_last - P_before): the pressure field's
      // tangent along the load path (negative values clipped: out of contact); the last solution is kept
      // for the next extrapolation.
      if (previous_.empty()) previous_.resize(static_cast<std::size_t>(n_));
      const double w = two_behind ? (mean_pressure - last_load_) / (last_load_ - previous_load_) : 0.0;
      const double s = s_[cur_];
      std::vector<T>& q = q_[cur_];
      for (std::size_t k = 0; k < q.size(); ++k) {
        const double p = s * static_cast<double>(q[k]);
        const double guess = p + w * (p - static_cast<double>(previous_[k]));
        previous_[k] = static_cast<T>(p);
        q[k] = static_cast<T>(std::max(guess, 0.0));
      }
      s_[cur_] = 1;
    }
    if (warm_) {  // the previous pressure (or its extrapolation) scaled to the new load
      s_[cur_] = total / q_sum(q_[cur_]);
    } else if (!active_set_) {  // the uniform pressure (active_set makes its own cold start)
      std::fill(q_[cur_].begin(), q_[cur_].end(), T(1));
      s_[cur_] = mean_pressure;
    }
    hardness_ = std::numeric_limits<double>::infinity();
    const Outcome outcome = active_set_
                                ? solve_active_set({.mean_pressure = mean_pressure, .hardness = hardness},
                                                   tolerance, max_iterations)
                                : iterate<true, false>(total, tolerance, max_iterations);
    warm_ = true;
    previous_load_ = last_load_;
    last_load_ = mean_pressure;
    ++loads_solved_;
    return outcome;
  }

  Outcome solve_separation(double separation, double hardness, double tolerance,
                           Index max_iterations) override {
    loads_solved_ = 0;
    separation_ = separation;
    hardness_ = stored(hardness);
    if (active_set_) {
      const Outcome outcome = solve_active_set(
          {.load_control = false, .separation = separation, .hardness = hardness}, tolerance, max_iterations);
      warm_ = true;
      return outcome;
    }
    if (!warm_) {
      // The surface's penetration of the flat, pressed in by the stiffness of a lone pixel (capped).
      const double stiffness = 1 / convolution_->self_response();
      for (Index i = 0; i < n_; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const double penetration = std::max(static_cast<double>(h_[k]) - separation, 0.0);
        q_[cur_][k] = static_cast<T>(std::min(penetration * stiffness, hardness));
      }
      s_[cur_] = 1;
    }
    const Outcome outcome = std::isfinite(hardness) ? iterate<false, true>(0, tolerance, max_iterations)
                                                    : iterate<false, false>(0, tolerance, max_iterations);
    warm_ = true;
    return outcome;
  }

  void impose_load(double mean_pressure, double given_hardness) override {
    // One pass to scale the elastic pressures, one application of G for the gap (a load-control gap pass).
    const double hardness = stored(given_hardness);
    std::vector<T>& q = q_[cur_];
    const double s = s_[cur_];
    double elastic = 0, plastic = 0;
    for (const T v : q) {
      const double p = s * static_cast<double>(v);
      if (p >= hardness)
        plastic += hardness;
      else
        elastic += p;
    }
    const double total = mean_pressure * static_cast<double>(n_);
    const double factor = elastic > 0 ? (total - plastic) / elastic : 1.0;
    for (T& v : q) {
      const double p = s * static_cast<double>(v);
      v = static_cast<T>(p >= hardness ? hardness : std::min(factor * p, hardness));
    }
    s_[cur_] = 1;
    hardness_ = hardness;
    separation_ = 0;
    // The gap of the result, with the flat from the mean gap on the elastic set.
    const Index nx = grid_.nx;
    const T* const q_data = q.data();
    const T h_cap = static_cast<T>(hardness);
    auto copy_in = [&](Index first, Index rows, T* buffer, Index ld, int) {
      for (Index r = 0; r < rows; ++r)
        std::copy_n(q_data + (first + r) * nx, nx, buffer + r * ld);
    };
    auto gap = [&](Index first, Index rows, const T* u, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        gap_rows<true, true>(part, q_data + i0, q_data + i0, u + r * ld, h_.data() + i0, g_.data() + i0, nx,
                             T(1), T(1), T(0), h_cap);
      }
    };
    clear_partials();
    convolution_->apply(Producer(copy_in), Consumer(gap));
    const Moments moments = combine_moments<true>();
    separation_ = -moments.g_mean;
    gap_offset_ = separation_;
    last_sum_ = moments.sum;
  }

  double separation() const override { return separation_; }
  double mean_pressure() const override { return last_sum_ / static_cast<double>(n_); }

  double max_pressure() const override {
    T largest = 0;
    for (const T v : q_[cur_])
      largest = std::max(largest, v);
    return s_[cur_] * static_cast<double>(largest);
  }

  double write(ContactSolution& s) const override {
    const Index nx = grid_.nx, ny = grid_.ny;
    s.pressure.resize(ny, nx);
    s.gap.resize(ny, nx);
    const std::vector<T>& q = q_[cur_];
    const double scale = s_[cur_];
    // On the team, each thread a block of points, the parts combined in thread order (the same sums every
    // run for a fixed thread count).
    struct Part {
      double residual = 0, sum = 0;
      Index contact = 0, plastic = 0;
    };
    std::vector<Part> parts(static_cast<std::size_t>(std::max(threads_, 1)));
#pragma omp parallel num_threads(static_cast <int>(parts.size()))
    {
      const Index thread = omp_get_thread_num(), team = omp_get_num_threads();
      Part part;
      for (Index i = n_ * thread / team; i < n_ * (thread + 1) / team; ++i) {
        const std::size_t k = static_cast<std::size_t>(i);
        const T pt = static_cast<T>(scale) * q[k];  // as the iteration computes it
        const double p = static_cast<double>(pt);
        s.pressure.data()[i] = p;
        part.sum += p;
        const double gap = static_cast<double>(g_[k]) + gap_offset_;
        if (!(pt > 0)) {
          s.gap.data()[i] = gap;
        } else {
          // Zero on the contact set; on plastic nodes too (the surface flowed to fit the flat there).
          s.gap.data()[i] = 0;
          ++part.contact;
          if (static_cast<double>(pt) >= hardness_)
            ++part.plastic;
          else
            part.residual = std::max(part.residual, std::abs(gap));
        }
      }
      parts[static_cast<std::size_t>(thread)] = part;
    }
    double residual = 0, sum = 0;
    Index contact = 0, plastic = 0;
    for (const Part& part : parts) {
      residual = std::max(residual, part.residual);
      sum += part.sum;
      contact += part.contact;
      plastic += part.plastic;
    }
    s.separation = separation_;
    s.contact_points = contact;
    s.plastic_points = plastic;
    // Relative to the height range (to 1 m for a flat surface, whose range is 0).
    s.residual = residual / (height_range_ > 0 ? height_range_ : 1.0);
    return sum / static_cast<double>(n_);
  }

 private:
  using Producer = typename Convolution<T>::Producer;
  using Consumer = typename Convolution<T>::Consumer;
  using Hook = typename Convolution<T>::Hook;

  struct Moments {
    double change = 0, sum = 0, elastic = 0, plastic = 0, g_mean = 0, g_norm = 0;
  };

  // The solver "active_set" (bem/active_set.hpp): from the start solve_load made or the last solution (when
  // warm), else from its own nested coarse start; leaves the state as iterate() does.
  Outcome solve_active_set(const ActiveSetProblem& problem, double tolerance, Index max_iterations) {
    std::vector<T> pressure;
    if (warm_) {
      pressure.resize(static_cast<std::size_t>(n_));
      const double s = s_[cur_];
      for (std::size_t k = 0; k < pressure.size(); ++k)
        pressure[k] = static_cast<T>(s * static_cast<double>(q_[cur_][k]));
    }
    ActiveSetOutcome result;
    try {
      result = active_set_solver_->solve(problem, tolerance, max_iterations, warm_, pressure, g_,
                                         this->between_iterations_);
    } catch (...) {
      forget();  // abandoned mid-solve: nothing to warm-start from
      throw;
    }
    q_[cur_] = std::move(pressure);
    s_[cur_] = 1;
    last_sum_ = result.pressure_sum;
    hardness_ = stored(problem.hardness);
    separation_ = result.separation;
    gap_offset_ = separation_;  // g holds u - h: the gap is g + d
    return Outcome{.iterations = result.iterations, .change = result.change, .converged = result.converged};
  }

  // The loop. kLoad: the load `total` (sum of p) is imposed: the gap is made zero-mean on the elastic set,
  // which fixes the flat, and p rescaled to the load. Else the flat's height is separation_: no mean taken
  // out, no rescaling. kHard: pressures capped at hardness_ (separation control only: under load control
  // the cap is met by a search on the flat's height, see PolonskyKeer::solve).
  template <bool kLoad, bool kHard>
  Outcome iterate(double total, double tolerance, Index max_iterations) {
    static_assert(!(kLoad && kHard));
    const Index nx = grid_.nx;
    const T* const h = h_.data();
    T* const g = g_.data();
    T* const t = t_.data();
    const T hardness = kHard ? static_cast<T>(hardness_) : std::numeric_limits<T>::infinity();
    const T offset = kLoad ? T(0) : static_cast<T>(separation_);  // g = offset - h + u

    // Consuming u = G q (unscaled): the new pressure s q, its change from s_old q_old, the gap, its moments.
    const T* q_new = nullptr;
    const T* q_old = nullptr;
    T s_new = 0, s_old = 0;
    auto gap = [&](Index first, Index rows, const T* u, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      const T sn = s_new, so = s_old;
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        gap_rows<kLoad, kHard>(part, q_new + i0, q_old + i0, u + r * ld, h + i0, g + i0, nx, sn, so, offset,
                               hardness);
      }
    };
    // Producing t = g - gbar + beta t on the elastic set (0 elsewhere).
    const T* q_cur = nullptr;
    T s_cur = 0, gbar = 0, beta = 0;
    auto direction = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      const T sc = s_cur, gb = gbar, b = beta;
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        direction_row<kHard>(part, q_cur + i0, g + i0, t + i0, buffer + r * ld, nx, sc, gb, b, hardness);
      }
    };
    // Preconditioned: producing the residual r = g - gbar on the elastic set (0 elsewhere), consuming its
    // filtered image, kept on the elastic set only as z (its mean there is taken out in the direction pass).
    // The filter serves load control only. Under separation control (and so with a hardness, which is met by
    // separation control) the residual is not the gap less its mean on the set: preconditioned that way the
    // iteration stopped after 6 iterations on surface A with a residual of 5 % of the height range and the
    // load 100 x off, yet "converged". Those solves iterate as plain Polonsky-Keer (python/tests/test_bem.py
    // checks that separation control gives the load back; active_set solves them itself).
    const bool preconditioned = preconditioner_ != nullptr && kLoad;
    T* const z = z_.data();
    auto residual = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      const T sc = s_cur, gb = gbar;
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        residual_row<kHard>(part, q_cur + i0, g + i0, buffer + r * ld, nx, sc, gb, hardness);
      }
    };
    auto filtered = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      const T sc = s_cur, gb = gbar;
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        filtered_row<kHard>(part, q_cur + i0, g + i0, buffer + r * ld, z + i0, nx, sc, gb, hardness);
      }
    };
    T zbar = 0;
    auto preconditioned_direction = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      const T sc = s_cur, gb = gbar, zb = zbar, b = beta;
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        preconditioned_direction_row<kHard>(part, q_cur + i0, g + i0, z + i0, t + i0, buffer + r * ld, nx, sc,
                                            gb, zb, b, hardness);
      }
    };
    // Consuming r = G t: its sum on the elastic set (its mean is taken out: PK's step for the unknown flat).
    auto response = [&](Index first, Index rows, const T* buffer, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      for (Index r = 0; r < rows; ++r)
        response_row(part, q_cur + (first + r) * nx, buffer + r * ld, nx);
    };
    // Producing the update q = max(p - tau t, 0) (capped at H); nodes out of contact that the surface
    // penetrates enter with -tau g (PK eq. 14), plastic nodes that open leave with H - tau g.
    T tau = 0, tau_enter = 0;
    T* q_next = nullptr;
    auto update = [&](Index first, Index rows, T* buffer, Index ld, int thread) {
      Partial& part = partial_[static_cast<std::size_t>(thread)];
      const T sc = s_cur, step = tau, enter = tau_enter, gb = gbar;
      for (Index r = 0; r < rows; ++r) {
        const Index i0 = (first + r) * nx;
        update_row<kHard>(part, q_cur + i0, t + i0, g + i0, q_next + i0, buffer + r * ld, nx, sc, step, enter,
                          gb, hardness);
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
    q_new = q_old = q_[cur_].data();
    s_new = s_old = static_cast<T>(s_[cur_]);
    clear_partials();
    convolution_->apply(Producer(copy_in), Consumer(gap));
    Moments moments = combine_moments<kLoad>();

    double g_norm_old = 1, delta = 0, change = 0;  // delta = 0: the first step is steepest descent
    double rz_old = 1;                             // preconditioned: <r, z> of the last direction
    double entered = 0;                            // nodes that entered (or left) the set in the last update
    // Step damping. On a contact set with hundreds of nodes at one height (a flat around a spike) PK's full
    // step drives hundreds of nodes out of the set and its entry step (eq. 14) drives as many back in, every
    // iteration, for ever (tests/test_bem_validation.cpp: a cycle with a relative change ~1.3 for 20000
    // iterations). A cycle shows as a relative change that stops decreasing: after kStall iterations without
    // a new lowest change, the steps are halved (deterministic; never below 2^-30 of PK's). A small enough
    // step is projected gradient descent on a convex quadratic, which converges; on problems without a
    // cycle the damping never starts and the iteration is PK's.
    constexpr Index kStall = 25;
    double damping = 1, lowest_change = std::numeric_limits<double>::infinity();
    Index since_lowest = 0;
    Outcome outcome;
    Index iteration = 0;
    for (;;) {
      if (iteration > 0) {
        // PK's criterion: the relative change of the pressure in the last iteration.
        change = moments.sum > 0 ? moments.change / moments.sum
                                 : (moments.change == 0 ? 0.0 : std::numeric_limits<double>::infinity());
        // The preconditioned solver also asks that no node entered or left the contact set in the last
        // update (docs/solvers.md: the active set has settled, so the change measures the CG on a fixed set).
        if (change < tolerance && (!preconditioned || entered == 0)) {
          outcome.converged = true;
          break;
        }
        if (change < lowest_change) {
          lowest_change = change;
          since_lowest = 0;
        } else if (++since_lowest >= kStall && damping > 0x1p-30) {
          damping *= 0.5;
          since_lowest = 0;
          lowest_change = change;
        }
      }
      if (iteration == max_iterations) break;
      if (this->between_iterations_) {
        try {
          this->between_iterations_();
        } catch (...) {
          forget();  // the fields are mid-iteration: nothing to warm-start from
          throw;
        }
      }
      if (kLoad && moments.elastic == 0) throw Error("Polonsky-Keer: the contact set became empty");
      // The gap made zero-mean on the elastic set (load control), the conjugate direction there (PK eq. 11),
      // restarted after the set grew (delta = 0).
      q_cur = q_[cur_].data();
      s_cur = static_cast<T>(s_[cur_]);
      gbar = static_cast<T>(moments.g_mean);
      if (preconditioned) {
        // z = the filtered residual on the elastic set, zbar its mean there (load control); Fletcher-Reeves'
        // beta of the preconditioned CG, <r, z - zbar> over the last one (r has zero mean on the set).
        clear_partials();
        preconditioner_->apply(Producer(residual), Consumer(filtered));
        double rz = 0, z_sum = 0, r_sum = 0;
        for (const Partial& part : partial_) {
          rz += part.rz;
          z_sum += part.z_sum;
          r_sum += part.rr_sum;
        }
        const double z_mean = kLoad ? z_sum / moments.elastic : 0.0;
        zbar = static_cast<T>(z_mean);
        const double rz_centred = rz - z_mean * r_sum;
        beta = static_cast<T>(delta > 0 && rz_old > 0 ? rz_centred / rz_old : 0.0);
        rz_old = rz_centred;
      } else {
        beta = static_cast<T>(delta > 0 && g_norm_old > 0 ? moments.g_norm / g_norm_old : 0.0);
        g_norm_old = moments.g_norm;
      }
      clear_partials();
      const double t_r =
          convolution_->apply(preconditioned ? Producer(preconditioned_direction) : Producer(direction),
                              kLoad ? Consumer(response) : Consumer(), Hook(), true);
      double gt = 0, t_sum = 0, r_sum = 0, tt = 0;
      for (const Partial& part : partial_) {
        gt += part.gt;
        t_sum += part.t_sum;
        r_sum += part.r_sum;
        tt += part.tt;
      }
      // t . (r - rbar) on the elastic set; t is zero elsewhere, so t . r is the operator's own product.
      const double tr = kLoad ? t_r - r_sum / moments.elastic * t_sum : t_r;
      // No descent left on the contact set (tr = 0: the gap is already uniform there, e.g. a set of one
      // node) is not convergence: nodes outside it may still penetrate the flat. The update then moves no
      // contact node (tau = 0) and lets those enter; if none does, the pressure is unchanged and the
      // criterion stops the loop. The step. Nodes entering (or, plastic, leaving) the set take the step of
      // the descent; without one the stiffness of one pixel, 1/G(0).
      // Preconditioned, t is a pressure [Pa] and tau a number, so PK's entry (the overlap times tau) would
      // have the wrong dimension; entering nodes take the overlap times the plain step of t instead,
      // <t, t>/<t, G t> [Pa/m] (the stiffness t meets; docs/solvers.md).
      tau = tr > 0 ? static_cast<T>(damping * gt / tr) : T(0);
      if (preconditioned)
        tau_enter =
            static_cast<T>(damping * (tr > 0 && tt > 0 ? tt / tr : 1 / convolution_->self_response()));
      else
        tau_enter = tr > 0 ? tau : static_cast<T>(damping / convolution_->self_response());

      // The update, and with it the next gap.
      const int next = 1 - cur_;
      q_next = q_[next].data();
      q_new = q_next;
      q_old = q_cur;
      s_old = s_cur;
      clear_partials();
      convolution_->apply(Producer(update), Consumer(gap), Hook(rescale));
      cur_ = next;
      s_[cur_] = static_cast<double>(s_new);
      entered = 0;
      for (const Partial& part : partial_)
        entered += part.entered;
      delta = entered > 0 ? 0 : 1;
      moments = combine_moments<kLoad>();
      ++iteration;
    }
    outcome.iterations = iteration;
    outcome.change = change;
    last_sum_ = moments.sum;
    if constexpr (kLoad) {
      separation_ = -moments.g_mean;  // the flat, from the mean gap on the contact set
      gap_offset_ = separation_;      // g holds u - h: the gap is g + d
    } else {
      gap_offset_ = 0;  // g holds d - h + u already
    }
    return outcome;
  }

  // The element-wise work of the passes, a row at a time (restrict: nothing aliases). Branch-free, so that
  // the compiler vectorises: the sets are comparisons of the pressure, not stored masks.

  // Consuming u: gap g = s u - h + offset, change of the pressure, and the moments of the gap on the elastic
  // set. Under load control the mean and the sum of squares about the mean are needed; a sum of squares
  // about a fixed shift loses nothing when the shift is one of the values (the spread about it is the spread
  // about the mean), so each thread shifts by the first elastic gap it meets and the threads' moments are
  // combined exactly (Chan et al.). Separation control needs no mean: the sum of g^2.
  template <bool kLoad, bool kHard>
  CB_KERNEL static void gap_rows(Partial& part, const T* __restrict qn, const T* __restrict qo,
                                 const T* __restrict u, const T* __restrict h, T* __restrict g, Index nx,
                                 T s_new, T s_old, T offset, T hardness) {
    if (kLoad && !part.has_shift) {
      for (Index x = 0; x < nx; ++x)
        if (qn[x] > 0) {
          part.shift = static_cast<double>(s_new * u[x] - h[x] + offset);
          part.has_shift = true;
          break;
        }
    }
    const double shift = kLoad ? part.shift : 0.0;
    double change = 0, sum = 0, s1 = 0, s2 = 0, elastic = 0, plastic = 0;
#pragma omp simd reduction(+ : change, sum, s1, s2, elastic, plastic)
    for (Index x = 0; x < nx; ++x) {
      const T p = s_new * qn[x];
      change += static_cast<double>(std::abs(p - s_old * qo[x]));
      sum += static_cast<double>(p);
      const T gv = s_new * u[x] - h[x] + offset;
      g[x] = gv;
      const bool in = kHard ? (p > 0) & (p < hardness) : p > 0;
      const double d = in ? static_cast<double>(gv) - shift : 0.0;
      s1 += d;
      s2 += d * d;
      elastic += in ? 1.0 : 0.0;
      if constexpr (kHard) plastic += p >= hardness ? 1.0 : 0.0;
    }
    part.change += change;
    part.sum += sum;
    part.s1 += s1;
    part.s2 += s2;
    part.elastic += elastic;
    part.plastic += plastic;
  }

  template <bool kHard>
  CB_KERNEL static void direction_row(Partial& part, const T* __restrict q, const T* __restrict g,
                                      T* __restrict t, T* __restrict out, Index nx, T s, T gbar, T beta,
                                      T hardness) {
    double gt = 0, t_sum = 0;
#pragma omp simd reduction(+ : gt, t_sum)
    for (Index x = 0; x < nx; ++x) {
      const bool in = kHard ? (q[x] > 0) & (s * q[x] < hardness) : q[x] > 0;
      const T gc = g[x] - gbar;
      const T tv = in ? gc + beta * t[x] : T(0);
      t[x] = tv;
      out[x] = tv;
      gt += static_cast<double>(gc * tv);
      t_sum += static_cast<double>(tv);
    }
    part.gt += gt;
    part.t_sum += t_sum;
  }

  // Preconditioned: the residual r = g - gbar on the elastic set, 0 elsewhere, into the filter's input.
  template <bool kHard>
  CB_KERNEL static void residual_row(Partial& part, const T* __restrict q, const T* __restrict g,
                                     T* __restrict out, Index nx, T s, T gbar, T hardness) {
    double r_sum = 0;
#pragma omp simd reduction(+ : r_sum)
    for (Index x = 0; x < nx; ++x) {
      const bool in = kHard ? (q[x] > 0) & (s * q[x] < hardness) : q[x] > 0;
      const T rv = in ? g[x] - gbar : T(0);
      out[x] = rv;
      r_sum += static_cast<double>(rv);
    }
    part.rr_sum += r_sum;
  }

  // Preconditioned: the filtered residual w kept on the elastic set as z; sums z and r w there.
  template <bool kHard>
  CB_KERNEL static void filtered_row(Partial& part, const T* __restrict q, const T* __restrict g,
                                     const T* __restrict w, T* __restrict z, Index nx, T s, T gbar,
                                     T hardness) {
    double z_sum = 0, rz = 0;
#pragma omp simd reduction(+ : z_sum, rz)
    for (Index x = 0; x < nx; ++x) {
      const bool in = kHard ? (q[x] > 0) & (s * q[x] < hardness) : q[x] > 0;
      const T zv = in ? w[x] : T(0);
      z[x] = zv;
      z_sum += static_cast<double>(zv);
      rz += in ? static_cast<double>(g[x] - gbar) * static_cast<double>(zv) : 0.0;
    }
    part.z_sum += z_sum;
    part.rz += rz;
  }

  // Preconditioned: t = (z - zbar) + beta t on the elastic set (0 elsewhere); sums (g - gbar) t, t and t^2.
  template <bool kHard>
  CB_KERNEL static void preconditioned_direction_row(Partial& part, const T* __restrict q,
                                                     const T* __restrict g, const T* __restrict z,
                                                     T* __restrict t, T* __restrict out, Index nx, T s,
                                                     T gbar, T zbar, T beta, T hardness) {
    double gt = 0, t_sum = 0, tt = 0;
#pragma omp simd reduction(+ : gt, t_sum, tt)
    for (Index x = 0; x < nx; ++x) {
      const bool in = kHard ? (q[x] > 0) & (s * q[x] < hardness) : q[x] > 0;
      const T tv = in ? (z[x] - zbar) + beta * t[x] : T(0);
      t[x] = tv;
      out[x] = tv;
      gt += in ? static_cast<double>(g[x] - gbar) * static_cast<double>(tv) : 0.0;
      t_sum += static_cast<double>(tv);
      tt += static_cast<double>(tv) * static_cast<double>(tv);
    }
    part.gt += gt;
    part.t_sum += t_sum;
    part.tt += tt;
  }

  CB_KERNEL static void response_row(Partial& part, const T* __restrict q, const T* __restrict r, Index nx) {
    double r_sum = 0;
#pragma omp simd reduction(+ : r_sum)
    for (Index x = 0; x < nx; ++x) {
      const double v = static_cast<double>(r[x]);
      r_sum += q[x] > 0 ? v : 0.0;
    }
    part.r_sum += r_sum;
  }

  template <bool kHard>
  CB_KERNEL static void update_row(Partial& part, const T* __restrict qc, const T* __restrict t,
                                   const T* __restrict g, T* __restrict qn, T* __restrict out, Index nx, T s,
                                   T tau, T tau_enter, T gbar, T hardness) {
    double q_sum = 0, entered = 0;
#pragma omp simd reduction(+ : q_sum, entered)
    for (Index x = 0; x < nx; ++x) {
      const T p = s * qc[x];
      const T gc = g[x] - gbar;
      const T moved_to = -tau_enter * gc;  // entering: the penetration times the step
      T v;
      bool moved;
      if constexpr (kHard) {
        // t = 0 off the elastic set, so the step leaves plastic nodes at H and the rest at 0. Nodes entering
        // or leaving move at most halfway into [0, H]: into the elastic set, whose conjugate gradient then
        // accounts for how they press on each other. (Moved all the way, to H or to 0, as PK's entry step
        // would, many nodes at once overshoot together: a cycle between all plastic and all released.)
        const T stepped = std::min(std::max(p - tau * t[x], T(0)), hardness);
        const bool enter = (p <= 0) & (gc < 0), leave = (p >= hardness) & (gc > 0);
        const T middle = hardness / 2;
        v = enter ? std::min(moved_to, middle) : (leave ? std::max(hardness + moved_to, middle) : stepped);
        moved = enter | leave;
      } else {
        const T stepped = std::max(p - tau * t[x], T(0));
        moved = (p <= 0) & (gc < 0);
        v = moved ? moved_to : stepped;
      }
      qn[x] = v;
      out[x] = v;
      q_sum += static_cast<double>(v);
      entered += moved ? 1.0 : 0.0;
    }
    part.q_sum += q_sum;
    part.entered += entered;
  }

  template <bool kLoad>
  Moments combine_moments() const {
    Moments m;
    for (const Partial& part : partial_) {
      m.change += part.change;
      m.sum += part.sum;
      m.elastic += part.elastic;
      m.plastic += part.plastic;
    }
    if (m.elastic == 0) return m;
    if constexpr (kLoad) {
      double mean = 0;
      for (const Partial& part : partial_)
        if (part.elastic > 0) mean += part.elastic * part.shift + part.s1;
      mean /= m.elastic;
      double norm = 0;
      for (const Partial& part : partial_)
        if (part.elastic > 0) {
          const double own = part.shift + part.s1 / part.elastic;
          norm += part.s2 - part.s1 * part.s1 / part.elastic + part.elastic * (own - mean) * (own - mean);
        }
      m.g_mean = mean;
      m.g_norm = std::max(norm, 0.0);
    } else {
      for (const Partial& part : partial_)
        m.g_norm += part.s2;
    }
    return m;
  }

  static double q_sum(const std::vector<T>& q) {
    double sum = 0;
    for (const T v : q)
      sum += static_cast<double>(v);
    return sum;
  }

  void clear_partials() {
    for (Partial& part : partial_)
      part.clear();
  }

  Grid grid_;
  Real modulus_;
  int threads_;
  bool active_set_;  // the solver "active_set": load control by bem/active_set.hpp
  std::unique_ptr<ActiveSetSolver<T>> active_set_solver_;  // its solver (null for the others)
  std::unique_ptr<Convolution<T>> convolution_;
  Index n_;
  std::vector<T> h_, g_, t_;
  std::unique_ptr<Convolution<T>> preconditioner_;  // null: plain Polonsky-Keer
  std::vector<T> z_;                                // the filtered residual (preconditioned only)
  std::vector<T> q_[2];
  double s_[2] = {1, 1};
  int cur_ = 0;
  std::vector<Partial> partial_;
  double height_range_ = 0;
  double separation_ = 0, gap_offset_ = 0, last_sum_ = 0;
  double hardness_ = std::numeric_limits<double>::infinity();
  bool warm_ = false;
  // For extrapolated starts: the loads of the last two load-controlled solves and the pressure of the one
  // before the last (the last is q_[cur_]); a solve under separation control ends the series.
  std::vector<T> previous_;
  double last_load_ = 0, previous_load_ = 0;
  Index loads_solved_ = 0;
};

PolonskyKeer::PolonskyKeer(const Surface& surface, Real modulus, PolonskyKeerOptions options, int threads)
    : surface_(surface.centred()), options_(options), engine_modulus_(modulus), threads_(threads) {
  if (!(options_.tolerance > 0) || options_.max_iterations < 1)
    throw Error("Polonsky-Keer: tolerance must be > 0 and max_iterations >= 1");
  if (options_.hardness && !(std::isfinite(*options_.hardness) && *options_.hardness > 0))
    throw Error("Polonsky-Keer: the hardness must be finite and > 0 Pa, got " +
                std::to_string(*options_.hardness));
  if (options_.single_precision && options_.tolerance < kSinglePrecisionTolerance)
    throw Error("Polonsky-Keer: single precision cannot reach a relative pressure change of " +
                std::to_string(options_.tolerance) + " (float resolves about 1e-7); use a tolerance >= " +
                std::to_string(kSinglePrecisionTolerance) + " or double precision");
  if (options_.single_precision)
    engine_ = std::make_unique<PolonskyKeerCore<float>>(surface_, modulus, threads, options_.solver);
  else
    engine_ = std::make_unique<PolonskyKeerCore<double>>(surface_, modulus, threads, options_.solver);
  engine_->set_between_iterations(options_.between_iterations);
}

PolonskyKeer::~PolonskyKeer() = default;

namespace {

PolonskyKeer::Engine::Outcome solve_capped(PolonskyKeer::Engine& engine, const HeightMap& heights,
                                           const PolonskyKeerOptions& options, Real mean_pressure);

void warn_not_converged(const char* what, Real value, const ContactSolution& s,
                        const PolonskyKeerOptions& options) {
  if (!options.warning) return;
  std::ostringstream text;
  text << "Polonsky-Keer did not converge at " << what << " = " << value << " in " << s.iterations
       << " iterations (relative pressure change " << s.change << ", tolerance " << options.tolerance
       << "; gap on the contact set " << s.residual << " of the height range, accepted up to "
       << residual_bound(options.tolerance) << "); the result is marked converged = false";
  options.warning(text.str());
}

// Converged only with a small complementarity residual as well (residual_bound, polonsky_keer.hpp).
bool residual_settled(const ContactSolution& s, const PolonskyKeerOptions& options) {
  return s.residual <= residual_bound(options.tolerance);
}

}  // namespace

const ContactSolution& PolonskyKeer::solve(Real mean_pressure) {
  if (!(std::isfinite(mean_pressure) && mean_pressure >= 0))
    throw Error("Polonsky-Keer: the mean pressure must be finite and >= 0 Pa, got " +
                std::to_string(mean_pressure));
  if (options_.hardness && mean_pressure >= *options_.hardness)
    throw Error("Polonsky-Keer: the mean pressure " + std::to_string(mean_pressure) +
                " Pa is at or above the hardness " + std::to_string(*options_.hardness) +
                " Pa: that is full plastic contact (p = H everywhere, the flat's height undetermined), "
                "which has no elastic solution to compute");
  const auto start = std::chrono::steady_clock::now();
  const HeightMap& h = surface_.heights();
  if (mean_pressure == 0) {
    // No load, no contact: the flat rests at the highest point, touching nothing (the set {h > d} is empty).
    solution_ = ContactSolution{};
    solution_.pressure = HeightMap::Zero(h.rows(), h.cols());
    solution_.separation = h.maxCoeff();
    solution_.gap = solution_.separation - h;
    solution_.converged = true;
    engine_->forget();  // nothing to start the next load from
    solution_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return solution_;
  }
  Index coarse_iterations = 0;
  if (options_.coarse_start && !engine_->warm()) coarse_iterations = start_coarse(mean_pressure);
  const Real hardness = options_.hardness.value_or(std::numeric_limits<Real>::infinity());
  const Engine::Outcome outcome =
      engine_->solve_load(mean_pressure, hardness, options_.tolerance, options_.max_iterations,
                          options_.load_path == LoadPathStart::extrapolated);
  Index iterations = outcome.iterations;
  Real change = outcome.change;
  bool converged = outcome.converged;
  if (options_.hardness && !engine_->caps_load_control() && engine_->max_pressure() > *options_.hardness) {
    const Engine::Outcome capped = solve_capped(*engine_, surface_.heights(), options_, mean_pressure);
    iterations += capped.iterations;
    change = capped.change;
    converged = converged && capped.converged;
  }
  engine_->write(solution_);
  solution_.mean_pressure = mean_pressure;
  solution_.iterations = iterations;
  solution_.coarse_iterations = coarse_iterations;
  solution_.change = change;
  solution_.converged = converged && residual_settled(solution_, options_);
  converged = solution_.converged;
  solution_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!converged) warn_not_converged("P/A0", mean_pressure, solution_, options_);
  return solution_;
}

const ContactSolution& PolonskyKeer::solve_for_separation(Real separation) {
  if (!std::isfinite(separation))
    throw Error("Polonsky-Keer: the separation must be finite, got " + std::to_string(separation));
  if (surface_.grid().periodic && !options_.hardness && !(separation > 0))
    throw Error(
        "Polonsky-Keer: on a periodic surface the separation is the mean gap and must be > 0 m (a "
        "mean gap of zero or less needs an infinite load), got " +
        std::to_string(separation));
  const auto start = std::chrono::steady_clock::now();
  const HeightMap& h = surface_.heights();
  if (separation >= h.maxCoeff()) {
    // At or above the highest point: no contact, and p = 0 satisfies every condition (u = 0, g = d - h >= 0).
    solution_ = ContactSolution{};
    solution_.pressure = HeightMap::Zero(h.rows(), h.cols());
    solution_.separation = separation;
    solution_.gap = separation - h;
    solution_.converged = true;
    engine_->forget();
    solution_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return solution_;
  }
  const Engine::Outcome outcome =
      engine_->solve_separation(separation, options_.hardness.value_or(std::numeric_limits<Real>::infinity()),
                                options_.tolerance, options_.max_iterations);
  solution_.mean_pressure = engine_->write(solution_);
  solution_.iterations = outcome.iterations;
  solution_.change = outcome.change;
  solution_.converged = outcome.converged && residual_settled(solution_, options_);
  solution_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!solution_.converged) warn_not_converged("separation [m]", separation, solution_, options_);
  return solution_;
}

Index PolonskyKeer::start_coarse(Real mean_pressure) {
  // The surface averaged over 2 x 2 blocks (its mean kept, so the load is the same), solved loosely (itself
  // from a coarser start, down to kCoarsest points a side), its pressure injected: each coarse pixel's
  // pressure on its four fine pixels. Elastic: a hardness is met afterwards by the fine solve.
  constexpr Index kCoarsest = 64;
  constexpr Real kCoarseTolerance = 1e-4;
  const Grid& fine = surface_.grid();
  if (fine.nx % 2 != 0 || fine.ny % 2 != 0 || fine.nx / 2 < kCoarsest || fine.ny / 2 < kCoarsest) return 0;
  Grid grid = fine;
  grid.nx /= 2;
  grid.ny /= 2;
  const HeightMap& h = surface_.heights();
  HeightMap coarse(grid.ny, grid.nx);
  for (Index y = 0; y < grid.ny; ++y)
    for (Index x = 0; x < grid.nx; ++x)
      coarse(y, x) =
          0.25 * (h(2 * y, 2 * x) + h(2 * y, 2 * x + 1) + h(2 * y + 1, 2 * x) + h(2 * y + 1, 2 * x + 1));
  PolonskyKeerOptions options = options_;
  options.tolerance = std::max(options_.tolerance, kCoarseTolerance);
  options.hardness = std::nullopt;
  options.load_path = LoadPathStart::scaled;
  PolonskyKeer solver(Surface(grid, coarse), engine_modulus_, options, threads_);
  const ContactSolution& s = solver.solve(mean_pressure);
  HeightMap start(fine.ny, fine.nx);
  for (Index y = 0; y < fine.ny; ++y)
    for (Index x = 0; x < fine.nx; ++x)
      start(y, x) = s.pressure(y / 2, x / 2);
  engine_->start_from(start);
  return s.iterations + s.coarse_iterations;
}

namespace {

// The capped solution under load control: the flat's height d searched, each trial a capped solve under
// separation control (warm-started from the last), until the mean pressure is the load to the tolerance.
// Starts from the elastic solution just computed: its d carries less than the load once capped, and lower
// flats carry more (the load is a continuous, non-increasing function of d). Leaves the engine at the
// trial that met the tolerance, with the elastic pressures then rescaled to the load exactly.
PolonskyKeer::Engine::Outcome solve_capped(PolonskyKeer::Engine& engine, const HeightMap& heights,
                                           const PolonskyKeerOptions& options, Real mean_pressure) {
  constexpr int kMaxTrials = 200;
  const Real hardness = *options.hardness;
  PolonskyKeer::Engine::Outcome total;
  total.converged = true;
  int trials = 0;
  // The excess of the capped mean pressure over the load with the flat at d.
  auto excess = [&](Real d) {
    const auto o = engine.solve_separation(d, hardness, options.tolerance, options.max_iterations);
    total.iterations += o.iterations;
    total.change = o.change;
    total.converged = total.converged && o.converged;
    ++trials;
    return engine.mean_pressure() - mean_pressure;
  };
  const Real target = options.tolerance * mean_pressure;
  auto done = [&](Real f) { return std::abs(f) <= target || trials >= kMaxTrials; };
  const Real top = heights.maxCoeff();
  const Real range = std::max(top - heights.minCoeff(), std::numeric_limits<Real>::min());
  // Bracket: d_hi carries at most the load, d_lo at least; steps double from the elastic approach.
  Real d = engine.separation(), f = excess(d);
  Real d_lo = d, f_lo = f, d_hi = d, f_hi = f;
  // First step: the approach times the relative shortfall (a contact's load grows faster than its approach,
  // so this overshoots a little and brackets), then doubling.
  Real step = std::max((top - d) * std::abs(f) / mean_pressure, 1e-6 * range);
  while (!done(f) && f < 0) {
    d_hi = d;
    f_hi = f;
    d -= step;
    step *= 2;
    f = excess(d);
    d_lo = d;
    f_lo = f;
  }
  while (!done(f) && f_hi > 0) {  // not expected (see above), but then search upwards
    d_lo = d;
    f_lo = f;
    d += step;
    step *= 2;
    f = excess(d);
    d_hi = d;
    f_hi = f;
  }
  // Regula falsi with the Illinois modification, bisection when it would leave the bracket; stops at the
  // tolerance on the load, or when the bracket is a rounding error wide.
  int side = 0;
  while (!done(f) && d_hi - d_lo > 4 * std::numeric_limits<Real>::epsilon() * (std::abs(d_lo) + range)) {
    d = d_hi - f_hi * (d_hi - d_lo) / (f_hi - f_lo);
    if (!(d > d_lo && d < d_hi)) d = 0.5 * (d_lo + d_hi);
    f = excess(d);
    if (f >= 0) {  // carries at least the load: the new lower end
      d_lo = d;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      d_hi = d;
      f_hi = f;
      if (side == +1) f_lo *= 0.5;
      side = +1;
    }
  }
  if (std::abs(f) > target) total.converged = false;
  engine.impose_load(mean_pressure, hardness);
  return total;
}

}  // namespace

}  // namespace contactbench
