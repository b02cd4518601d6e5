// The default solver, the primal-dual active-set method (bem/active_set.hpp, docs/solvers.md "The
// active-set method"), on slabs (docs/mpi.md "The default solver"): the serial method's steps
// (bem/solvers/active_set_*.cpp) with each rank holding its slab of the heights, pressure, displacement and
// the CG's vectors, the operator and the filter as distributed convolutions (mpi/distributed_half_space.hpp:
// on two ranks and more the slab engine, mpi/slab_convolution_engine.hpp), every global
// sum combined in rank order from an MPI_Allgather (so every rank takes the same decisions), the extended
// filter's window sums over a halo of kExtensionRadius rows (mpi/row_exchange.hpp, from further ranks when
// a slab is thinner), the few changed nodes' columns of G added by the operator applied to those changes
// alone (no whole response kept), and the cold start's k-th largest score selected over the ranks
// (mpi/distributed_selection.hpp). The nested coarse start: levels above kGatherBound points restricted on
// slabs (mpi/distributed_restriction.hpp) and solved by this class, the first level at or below it gathered
// to every rank and solved by the serial ActiveSetSolver itself (identical on every rank), the pressure
// interpolated back on slabs (bem/solvers/interpolate_up.hpp, the serial kernel).
//
// What differs from one process, all round-off: the order of the sums (per rank instead of per thread), the
// transforms (the slab engine's or FFTW-MPI's passes), the window sums' running order, and the filter: in
// single precision on the slab engine as the serial filter, elsewhere in double on FFTW-MPI with its input
// and output rounded to float as the serial filter rounds them (its inner passes then run in double).
// Measured against the serial method: tests/mpi/test_mpi_active_set.cpp.
// Double precision only.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <mpi.h>

#include "contactbench/bem/active_set.hpp"
#include "contactbench/bem/box_sum.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/mpi/distributed_convolution.hpp"
#include "contactbench/mpi/distributed_half_space.hpp"
#include "contactbench/mpi/row_exchange.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

class DistributedActiveSet {
 public:
  // Coarse levels of at most this many points are gathered to every rank and solved by the serial method
  // (a 256^2 level: 512 kB a field on each rank); larger ones stay on slabs.
  static constexpr Index kGatherBound = 256 * 256;

  // Collective. local_heights: this rank's slab (slab_of(grid, comm)) of the centred heights, row-major.
  // `threads`: FFTW's threads a rank (the element-wise passes run on one). `gather_bound`: the coarse
  // levels gathered have at most this many points (0: every level on slabs).
  DistributedActiveSet(const Grid& grid, std::vector<double> local_heights, Real modulus, MPI_Comm comm,
                       int threads = 1, Index gather_bound = kGatherBound);
  ~DistributedActiveSet();
  DistributedActiveSet(const DistributedActiveSet&) = delete;
  DistributedActiveSet& operator=(const DistributedActiveSet&) = delete;

  // As ActiveSetSolver::solve, on this rank's slab of the pressure (in: the start when `warm`, else ignored;
  // out: the solution). Collective; `between` runs on every rank before each inner iteration.
  ActiveSetOutcome solve(const ActiveSetProblem& problem, double tolerance, Index max_iterations, bool warm,
                         std::vector<double>& pressure, const std::function<void()>& between = {});
  // G p - h of the last solution on this rank's slab.
  void displacement_minus_heights(std::vector<double>& out) const;
  double displacement_minus_height(std::size_t k) const { return u_[k] - h_[k]; }
  // This rank's slab of the centred heights.
  const std::vector<double>& heights() const { return h_; }
  const Slab& slab() const { return slab_; }
  // The fraction of all nodes in contact in the last solution.
  double contact_fraction() const { return contact_fraction_; }
  // The most bytes this rank holds at once during a solve (fields, operator, filter, work arrays; the coarse
  // levels' peak once a cold solve has made them: docs/mpi.md "Memory a point").
  std::size_t bytes() const;
  // What it holds from one solve to the next (heights, displacement, transform, multipliers).
  std::size_t kept_bytes() const;

 private:
  struct Sums {
    double a = 0, b = 0, c = 0, d = 0, g = 0, h = 0;  // combined as sums
    double e = 0, f = 0;                              // combined as maxima
    void add(const Sums& o);
  };
  struct CgStep {
    double c = 0, shift_c = 0, to_filter = 1, from_filter = 1, zbar = 0, beta = 0, tau = 0, rz = 0, t_gt = 0;
    Index radius = 0;
  };
  struct Change {
    double node = 0;  // global index (exact in a double below 2^53)
    double dp = 0;
  };
  class Coarse;

  double threshold(double tolerance, double d) const;
  Index extension_radius() const;
  // This rank's Sums combined with every rank's, in rank order (the same on every rank).
  Sums reduced(const Sums& mine) const;
  template <class Body>
  Sums over_points(Body body);
  template <class Input, class Output>
  Sums fresh_displacement(std::vector<double>& p, Input on_input, Output on_output);
  static double flat_height(const Sums& s) { return s.b > 0 ? -s.a / s.b : 0; }
  static bool load_scale(double elastic, double plastic, double total, double& factor);
  static void add_residual(Sums& part, double x);
  double start_score(const std::vector<double>& p, std::size_t k, double d, double stiffness) const;
  bool converged(Index changed, bool above_cap, double residual, double limit, double tolerance) const {
    return changed == 0 && !above_cap && residual <= limit && last_step_change_ <= tolerance;
  }

  void measure_heights();
  std::size_t work_bytes() const;
  void make_work();
  void free_work();
  void finish(std::vector<double>& p, double total, double tolerance, double d, const Sums& kept, Index steps,
              ActiveSetOutcome& outcome);
  Sums update_sets(std::vector<double>& p, double d, double limit, double entry, bool capping);
  void reseat(std::vector<double>& p, double total);
  void keep_to_sets(std::vector<double>& p, std::size_t k, Sums& part);
  void add_columns(Index changed);
  void scale_pressure(std::vector<double>& p, double factor);
  bool scale_to(std::vector<double>& p, double total);
  void scale_with_displacement(std::vector<double>& p, double factor);
  Index cg_on_set(std::vector<double>& p, double scale, double reduction, double absolute, double step_change,
                  Index budget, const std::function<void()>& between);
  Sums count_on_set(std::vector<double>& p, double scale);
  void make_extension_weights(Index radius);
  // The window sums of the values value(k) of this rank's slab for each of its rows: emit(local_row, sums).
  template <class Value, class Emit>
  void window_sums(Value value, Emit emit);
  // The halo of the values fetched and the window restarted; then window_sums_of(r, value) for r = 0, 1, ...
  // in order, with the same values.
  template <class Value>
  void start_window_sums(Value value);
  template <class Value>
  const double* window_sums_of(Index r, Value value);
  const std::vector<double>& gathered(const double* mine, int count) const;
  double filter_pass(const CgStep& step, double& z_sum);
  Sums operator_pass(std::vector<double>& p, CgStep& step);
  Sums start_sets(std::vector<double>& p, bool warm, double total, double& d);
  double start_scale(const std::vector<double>& p, double total);
  double start_displacement(std::vector<double>& p, double factor);
  double coarse_area_level(const std::vector<double>& scores);
  ActiveSetOutcome nested_start(const ActiveSetProblem& problem, std::vector<double>& p,
                                const std::function<void()>& between);

  Grid grid_;
  MPI_Comm comm_;
  Slab slab_;
  std::vector<Slab> layout_;
  Real modulus_;
  int threads_;
  Index gather_bound_;
  DistributedHalfSpace operator_;
  std::unique_ptr<DistributedConvolution> filter_;
  std::size_t n_;  // this rank's points
  double points_;  // all ranks' points
  std::vector<double> h_, u_, r_, z_, t_;
  WindowRows window_;  // the window sums' rows, made once (start_window_sums restarts them)
  mutable std::vector<double> gathered_;  // gathered()'s buffer
  std::vector<float> extension_weight_;
  std::vector<std::uint16_t> window_count_;
  std::vector<std::uint8_t> in_, plastic_;
  std::unique_ptr<RowExchange> halo_;
  std::vector<Change> changes_;  // this rank's first kFewChanges changes of the last keep_to_sets pass
  bool load_control_ = true;
  double separation_ = 0;
  double cap_ = 0;
  double height_range_ = 1, highest_ = 0, gap_round_off_ = 0;
  double last_step_change_ = 0;
  bool displacement_current_ = false, displacement_fresh_ = false;
  double set_size_ = 1, set_mean_ = 0, contact_fraction_ = 0;
  double coarse_fraction_ = 0;   // of the coarse level's nodes, in contact in its solution
  bool has_coarse_ = false;      // a cold start solves the next coarser level first (made then, freed after)
  std::size_t coarse_peak_ = 0;  // the coarse level's bytes() when it last ran
};

}  // namespace contactbench::mpi
