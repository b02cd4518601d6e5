// The primal-dual active-set method (bem/active_set.hpp, docs/solvers.md "The active-set method") on one
// grid, with its next coarser level for the nested start: one class, its work split by concept over
//   active_set_method.cpp        the outer loop: the starting sets, the inner solves, the convergence test;
//   active_set_sets.cpp          the sets: their update's bookkeeping, the load they carry, G p kept current;
//   active_set_inner_cg.cpp      the inner CG on a fixed set, with the extended filter;
//   active_set_coarse_start.cpp  the nested coarse start and the cold start's sets.
// Internal to the solvers (bem/solvers/); callers use BemSolver.
#pragma once

#include <omp.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "contactbench/bem/active_set.hpp"
#include "contactbench/bem/box_sum.hpp"
#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/work_array.hpp"

namespace contactbench {

// The method's tuning, each value with what it was measured against.
namespace active_set_tuning {

// Inner solves stop at this relative reduction of the residual's L2 norm while the set still changes: a
// looser one needs more outer steps, a tighter one solves exactly on a set about to change (measured with a
// numpy prototype on surface A and an H = 0.8 surface, 256^2 to 1024^2: 0.1 among 0.03 to 0.3).
inline constexpr double kInnerReduction = 0.1;
// The coarsest level of the nested start, and the tolerance its levels are solved to (a start only).
inline constexpr Index kCoarsest = 64;
inline constexpr double kCoarseTolerance = 1e-3;
// The CG's displacement u (stepped, not made afresh) is kept as the output's when its drift from G p is
// this many times below the convergence threshold.
inline constexpr double kDriftMargin = 1000;
// A set update that changes at most this many pressures brings G p up to date by their columns of G (a
// pass over the grid: measured at 256^2, 1024^2 and 2048^2, 16 nodes cost about half a fresh G p, periodic,
// and a quarter non-periodic; one node a tenth) instead of a fresh transform.
inline constexpr std::size_t kFewChanges = 16;
// With plastic nodes G p does not scale with p, so an outer step that rescales the pressures to the load
// makes G p afresh (an application of G). The factor is a ratio of sums over the grid whose last bits depend
// on the order of the sums (threads', ranks'): within this of 1 it counts as 1 for that choice (the
// pressures are still scaled by it, and u keeps its drift check, kDriftMargin), so one process and the ranks
// choose alike. The sums' round-off is about sqrt(n) eps (1e-12 at 4096^2, 1.5e-11 at 65536^2).
inline constexpr double kUnitScaleSlack = 1e-10;
inline bool rescales_the_load(double factor) {
  return std::abs(factor - 1) > kUnitScaleSlack;
}
// A guard against a set that cycles: at most this many outer steps (each ends an inner solve).
inline constexpr Index kMaxOuter = 500;
// Nodes enter the contact set when they penetrate beyond the gap's round-off for this many outer steps, then
// only beyond the convergence threshold (docs/solvers_log.md "Which nodes enter"): a node at p = 0 and g = 0
// within the solve's accuracy could otherwise enter and leave again for ever. Solves in tests/ take 5 to 16
// outer steps.
inline constexpr Index kLaxEntrySteps = 30;
// The extended filter (docs/solvers_log.md "The extended filter"): the residual is extended off the contact
// set by its average over the set nodes of a (2 kExtensionRadius + 1)^2 window before the Fourier filter, and
// the filter's output gathered back by the transpose. The average divides by the window's count of set nodes,
// but by at least kExtensionFloor of the window, so that a node with few set nodes near it gets a damped
// value, not one node's residual. Measured with `contactbench bem` at 1024^2 (surface A refined and an
// H = 0.8 surface, 1 %, 10 % and 30 % contact, seven cases): 210 / 197 / 191 / 195 iterations in all for
// radii 6 / 8 / 12 / 16, against 357 without the extension.
inline constexpr Index kExtensionRadius = 12;
inline constexpr double kExtensionFloor = 0.25;
// The preconditioner's filter runs in single precision, on plans FFTW estimates: measured float plans
// applied 3 % faster in the solve (surface A at 1024^2, 1 %, periodic: 0.159-0.168 s against 0.164-0.177 s)
// but cost about 1.1 s to make per process at 1024^2 (the double filter shared the operator's measured
// plans), which a scene of a few dozen solves never earns back (the paper's default scene: 7.1 s against
// 6.4 s before the float filter).
inline constexpr FftRigor kFilterPlans = FftRigor::estimate;
// The window counts kept with the weights are 16-bit (ActiveSet::window_count_).
static_assert((2 * kExtensionRadius + 1) * (2 * kExtensionRadius + 1) <=
              std::numeric_limits<std::uint16_t>::max());

}  // namespace active_set_tuning

template <class T>
class ActiveSet {
 public:
  // `rigor`: how the operator's plans are made (the finest level's by the run's work, the coarse levels'
  // estimated: make_coarse_level).
  ActiveSet(const Grid& grid, std::vector<T> heights, Real modulus, int threads,
            FftRigor rigor = FftRigor::by_work);
  // The method's solve (ActiveSetSolver::solve); leaves u_ as G p of the solution.
  ActiveSetOutcome solve(const ActiveSetProblem& problem, double tolerance, Index max_iterations, bool warm,
                         std::vector<T>& p, const std::function<void()>& between);
  void displacement_minus_heights(std::vector<T>& out);
  // New heights of the same grid; the coarse levels follow (active_set_coarse_start.cpp).
  void set_heights(const std::vector<T>& heights);

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
    return std::min(active_set_tuning::kExtensionRadius, (std::min(grid_.nx, grid_.ny) - 1) / 2);
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

  // The convergence test after a set update (docs/solvers.md "The active-set method, precisely"): no node
  // changed set and no elastic pressure is above the cap, the largest |gap| on the set (`residual`) is
  // within the threshold `limit`, and the last CG step changed the pressure by at most the tolerance.
  bool converged(Index changed, bool above_cap, double residual, double limit, double tolerance) const {
    return changed == 0 && !above_cap && residual <= limit && last_step_change_ <= tolerance;
  }
  void finish(std::vector<T>& p, double total, double tolerance, double d, const Sums& kept, Index steps,
              ActiveSetOutcome& outcome);

  // The sets (active_set_sets.cpp).
  Sums update_sets(std::vector<T>& p, double d, double limit, double entry, bool capping);
  void reseat(std::vector<T>& p, double total);
  void keep_to_sets(std::vector<T>& p, std::size_t k, Sums& part);
  void add_columns();
  void note_flips();
  void scale_pressure(std::vector<T>& p, double factor);
  bool scale_to(std::vector<T>& p, double total);
  void scale_with_displacement(std::vector<T>& p, double factor);
  // The inner CG (active_set_inner_cg.cpp).
  Index cg_on_set(std::vector<T>& p, double scale, double reduction, double absolute, double step_change,
                  Index budget, const std::function<void()>& between);
  template <class WeightOf>
  void update_weights(Index radius, WeightOf weight_of);
  // What the CG's two passes of an iteration share.
  struct CgStep {
    double c = 0;                           // the mean the steps added to r (load control)
    T shift_c = 0;                          // c as T
    double to_filter = 1, from_filter = 1;  // powers of two: the residual's scale into the filter and back
    T zbar = 0, beta = 0, tau = 0;
    double rz = 0, t_gt = 0;  // <r, z> and <t, G t>
    Index radius = 0;         // of the extension's window
  };
  Sums count_on_set(std::vector<T>& p, double scale);
  void make_extension_weights(Index radius);
  double filter_pass(const CgStep& step);
  void operator_pass(std::vector<T>& p, CgStep& step);
  // Of x = r - c on the set: its sum (a), sum of squares (b), largest value (e) and largest of -x (f).
  static void add_residual(Sums& part, double x) {
    part.a += x;
    part.b += x * x;
    part.e = std::max(part.e, x);
    part.f = std::max(part.f, -x);
  }
  // The starts (active_set_coarse_start.cpp).
  Sums start_sets(std::vector<T>& p, bool warm, double total, double& d);
  double start_scale(const std::vector<T>& p, double total);
  double start_displacement(std::vector<T>& p, double factor);
  std::size_t score_start(const std::vector<T>& p, double d, double stiffness);
  T coarse_area_level(std::size_t candidates);
  ActiveSetOutcome nested_start(const ActiveSetProblem& problem, std::vector<T>& p,
                                const std::function<void()>& between);
  void make_coarse_level();
  // The heights averaged over 2 x 2 blocks: the next coarser level's.
  std::vector<T> coarse_heights(const Grid& coarse_grid) const;
  // highest_, height_range_ and gap_round_off_ of h_.
  void measure_heights();

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

  // A cold start's score of node k, p - k g (k the stiffness of one pixel): the node starts in contact when
  // it is positive.
  T start_score(const std::vector<T>& p, std::size_t k, double d, double stiffness) const {
    const double g = d + static_cast<double>(u_[k]) - static_cast<double>(h_[k]);
    return static_cast<T>(static_cast<double>(p[k]) - stiffness * g);
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

  // The factor on the elastic pressures (summing to `elastic`; the plastic ones to `plastic`) that makes
  // the sum of p `total`; false when the plastic nodes alone carry `total` or more.
  static bool load_scale(double elastic, double plastic, double total, double& factor) {
    const double elastic_total = total - plastic;
    if (plastic > 0 && !(elastic_total > 0)) return false;
    factor = elastic > 0 ? elastic_total / elastic : 0;
    return true;
  }

  Grid grid_;
  std::vector<T> h_;
  Real modulus_;
  int threads_;
  std::unique_ptr<Convolution<T>> operator_;
  // The preconditioner's filter in single precision whatever T (cg_on_set).
  std::unique_ptr<Convolution<float>> filter_;
  std::size_t n_;
  // G p, the CG's residual, the filtered residual, the CG's direction: not zero-filled when made (u and z are
  // written before they are read; r and t are zeroed by the team that uses them, in the constructor).
  WorkArray<T> u_, r_, z_, t_;
  // Off the set: 1 / the window's count of set nodes (floored). In single precision whatever T: E and E^T
  // read the same weights, so the preconditioner stays symmetric, and each iteration reads them twice
  // (surface A at 1 % contact: the same iterations in the 30 cases, 2 to 4 % less time at 1024^2 and
  // 2048^2).
  WorkArray<float> extension_weight_;  // (written by make_extension_weights before any read)
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
  std::vector<std::array<Change, active_set_tuning::kFewChanges>>
      changes_;                            // per thread, recorded by keep_to_sets
  std::vector<T> response_;                // G e_0, the displacement of a unit pressure at node 0 (or empty)
  WorkArray<std::uint16_t> window_count_;  // per node: the set nodes in its window (with the weights)
  bool weights_current_ = false;           // the weights are those of the set before pending_flips_
  std::vector<std::vector<Flip>> flips_;   // per thread: the last set update's flips
  std::vector<Flip> pending_flips_;        // the flips since the weights were made
  double set_size_ = 1;                    // nodes in the set
  double set_mean_ = 0;                    // the mean of u - h on the set at the CG's end (load control)
  double contact_fraction_ = 0;            // of the nodes, in contact (p > 0) in the last solution
  std::unique_ptr<ActiveSet<T>> coarse_;   // the next coarser level of the nested start, once made
};

// Holds p at node k to the sets: H on the plastic set, 0 off both. Adds to `part` what the load's rescaling
// needs, a: the sum of p on the elastic set, b: its nodes, g: the sum of p on the plastic set; and c: 1
// when p changed. In this header so that the set update's pass and the start's inline it (out of line it
// was a call per node of the grid in every set update: issue 42).
template <class T>
inline void ActiveSet<T>::keep_to_sets(std::vector<T>& p, std::size_t k, Sums& part) {
  const T before = p[k];
  const T held = plastic_[k] ? cap_ : (in_[k] ? before : T(0));
  if (held != before) {  // stored only when changed: most nodes keep p = 0, their memory untouched
    p[k] = held;
    part.c += 1;
    if (part.c <= active_set_tuning::kFewChanges)  // the first few of each thread, for add_columns
      changes_[static_cast<std::size_t>(omp_get_thread_num())][static_cast<std::size_t>(part.c) - 1] = {
          k, static_cast<double>(held) - static_cast<double>(before)};
  }
  part.a += in_[k] ? static_cast<double>(held) : 0.0;
  part.b += in_[k];
  part.g += plastic_[k] ? static_cast<double>(cap_) : 0.0;
}

}  // namespace contactbench
