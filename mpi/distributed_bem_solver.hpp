// The boundary-element solver on slabs (docs/mpi.md): Polonsky & Keer's constrained conjugate gradient
// (bem/bem_solver.hpp, docs/theory.md section 6) with each rank holding its slab of the heights, pressure,
// gap and search direction, the half-space operator distributed (mpi/distributed_half_space.hpp), and every
// global sum of an iteration (the load, the gap's moments on the contact set, the step's products) reduced
// with MPI_Allreduce. The iteration is the serial one step for step (the same starts, steps, entry rule,
// damping and stopping criterion), so it takes the same iterations and finds the same contact set; the
// pressures agree to round-off.
//
// Also the preconditioned solver (its Fourier filter distributed), and the default solver, active_set
// (mpi/distributed_active_set.hpp, the serial method step for step with its nested coarse start; its
// warm start from the previous load's pressure scaled to the new load, as the serial solver's).
//
// Distributed so far: load control, double precision, elastic or (active_set only) capped at a hardness.
// Options that need more (a hardness with the PK solvers, single precision, separation control, coarse or
// extrapolated starts) are refused with an error naming them, never run approximately.
#pragma once

#include <memory>

#include <mpi.h>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/mpi/distributed_active_set.hpp"
#include "contactbench/mpi/distributed_half_space.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::cg {
struct Moments;  // bem/solvers/constrained_cg_kernels.hpp
}  // namespace contactbench::cg

namespace contactbench::mpi {

struct DistributedContactSolution {
  HeightMap pressure;        // this rank's slab [Pa]
  HeightMap gap;             // this rank's slab [m], 0 on the contact set
  Real mean_pressure = 0;    // P/A0 [Pa], as prescribed
  Real separation = 0;       // the flat's height above the mean plane [m]
  Index contact_points = 0;  // over all ranks
  Index plastic_points = 0;  // at p = H (with a hardness; 0 without), over all ranks, in contact_points too
  Index iterations = 0;
  Real change = 0;    // the last relative change of the pressure
  Real residual = 0;  // max |gap| on the contact set / (max h - min h), over all ranks
  bool converged = false;
};

class DistributedBemSolver {
 public:
  // Collective. local_heights: this rank's slab (slab_of(grid, comm)) of the surface; modulus E* [Pa].
  // options: single_precision, coarse_start and an extrapolated load path unset, a hardness with active_set
  // only (see above).
  // `threads`: FFTW's threads a rank, for the transforms (the element-wise passes run on one).
  DistributedBemSolver(const Grid& grid, const HeightMap& local_heights, Real modulus, MPI_Comm comm,
                       BemSolverOptions options, int threads = 1);
  ~DistributedBemSolver();

  // Solves for the mean pressure P/A0 >= 0 [Pa], warm-started from the previous load's solution (scaled), as
  // the serial solver. Collective.
  const DistributedContactSolution& solve(Real mean_pressure);
  const DistributedContactSolution& solution() const { return solution_; }
  const Slab& slab() const { return slab_; }
  // Bytes this rank holds for the solve (fields, operator, preconditioner, the solution's pressure and gap):
  // the memory per rank of docs/mpi.md "Memory a point".
  std::size_t bytes() const;
  // What bytes() will be, at most, for a rank holding `slab_points` of `grid`, before anything is allocated
  // (the preflight's memory check, app/distributed_stages.cpp). An upper bound: tests/mpi check bytes() <=
  // estimate <= 2 bytes() on 1-3 ranks.
  static std::size_t estimated_bytes(const Grid& grid, Index slab_points, const BemSolverOptions& options);

 private:
  void apply(const std::vector<double>& in, std::vector<double>& out);
  cg::Moments gap_pass(const std::vector<double>& q_new, const std::vector<double>& q_old, double s_new,
                       double s_old);
  void iterate(double total);
  void solve_active_set(double mean_pressure, double total);
  void write();

  Grid grid_;
  MPI_Comm comm_;
  BemSolverOptions options_;
  Slab slab_;
  std::unique_ptr<DistributedHalfSpace> operator_;  // the PK solvers' (active_set has its own)
  Index local_points_;
  std::unique_ptr<DistributedConvolution> preconditioner_;  // null: plain Polonsky-Keer
  std::unique_ptr<DistributedActiveSet> active_set_;        // the active-set method instead of PK's
  // h_ and g_ (G p - h) are the PK solvers' only: active_set keeps the heights and G p (active_set_'s).
  std::vector<double> h_, g_, t_, u_, z_, q_[2];
  bool unloaded_ = false;  // the last load was 0 (no contact, G p = 0)
  double s_[2] = {1, 1};
  int cur_ = 0;
  bool warm_ = false;
  double height_range_ = 0, separation_ = 0;
  Index iterations_ = 0;
  double change_ = 0;
  bool converged_ = false;
  DistributedContactSolution solution_;
};

}  // namespace contactbench::mpi
