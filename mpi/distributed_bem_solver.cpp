#include "contactbench/mpi/distributed_bem_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/bem/solvers/constrained_cg_kernels.hpp"
#include "contactbench/bem/solvers/load_stepping.hpp"
#include "contactbench/bem/solvers/polonsky_keer_step.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench::mpi {

namespace {

void refuse(bool unsupported, const std::string& what) {
  if (unsupported)
    throw Error(
        "distributed Polonsky-Keer: " + what +
        " is not distributed yet (docs/mpi.md); it supports load control, elastic, double precision, "
        "load_path = scaled, cold or solver, no coarse_start (solvers polonsky_keer, preconditioned_cg, "
        "active_set), a hardness with active_set only");
}

double max_over_ranks(double value, MPI_Comm comm) {
  double result = 0;
  MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, MPI_MAX, comm);
  return result;
}

double min_over_ranks(double value, MPI_Comm comm) {
  double result = 0;
  MPI_Allreduce(&value, &result, 1, MPI_DOUBLE, MPI_MIN, comm);
  return result;
}

// Several sums over the ranks at once (one MPI_Allreduce for an iteration's step).
template <std::size_t N>
void sum_over_ranks(double (&values)[N], MPI_Comm comm) {
  MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(N), MPI_DOUBLE, MPI_SUM, comm);
}

}  // namespace

DistributedBemSolver::DistributedBemSolver(const Grid& grid, const HeightMap& local_heights, Real modulus,
                                           MPI_Comm comm, BemSolverOptions options, int threads)
    : grid_(grid), comm_(comm), options_(std::move(options)), slab_(slab_of(grid, comm)) {
  if (!(options_.tolerance > 0) || options_.max_iterations < 1)
    throw Error("Polonsky-Keer: tolerance must be > 0 and max_iterations >= 1");
  // A hardness caps the pressure in the active-set method (its ActiveSetProblem::hardness); the PK solvers'
  // capped iteration (their impose_load search of the flat's height) is not distributed.
  refuse(options_.hardness.has_value() && options_.solver != SolverKind::active_set,
         "a hardness with solver " + std::string(solver_name(options_.solver)));
  refuse(options_.single_precision, "single precision");
  refuse(options_.coarse_start, "coarse_start");
  // It starts each load from the last scaled, the start every solver may take when left to choose.
  refuse(load_path_start(options_, grid) == LoadPathStart::extrapolated, "load_path = extrapolated");
  const Slab& slab = slab_;
  throw_on_any_rank(local_heights.rows() != slab.count || local_heights.cols() != grid.nx,
                    "distributed Polonsky-Keer: the local heights are " +
                        std::to_string(local_heights.cols()) + " x " + std::to_string(local_heights.rows()) +
                        " but this rank's slab is " + std::to_string(grid.nx) + " x " +
                        std::to_string(slab.count),
                    comm);
  local_points_ = slab.points();
  const std::size_t n = static_cast<std::size_t>(local_points_);
  // Centred on the global mean, as the serial solver centres the surface (Surface::centred).
  const double mean = sum_over_ranks(local_heights.sum(), comm) / static_cast<double>(grid.points());
  h_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    h_[i] = local_heights.data()[i] - mean;
  q_[0].assign(n, 0.0);
  const double local_max =
      n ? *std::max_element(h_.begin(), h_.end()) : -std::numeric_limits<double>::infinity();
  const double local_min =
      n ? *std::min_element(h_.begin(), h_.end()) : std::numeric_limits<double>::infinity();
  height_range_ = max_over_ranks(local_max, comm) - min_over_ranks(local_min, comm);
  if (options_.solver == SolverKind::active_set) {
    // Its own fields, the heights moved there; here only the pressure (q_[0]) between loads.
    active_set_ = std::make_unique<DistributedActiveSet>(grid, std::move(h_), modulus, comm, threads);
    h_ = {};
  } else {
    operator_ = std::make_unique<DistributedHalfSpace>(grid, modulus, comm, threads);
    g_.assign(n, 0.0);
    t_.assign(n, 0.0);
    u_.assign(n, 0.0);
    q_[1].assign(n, 0.0);
  }
  if (options_.solver == SolverKind::preconditioned_cg) {
    preconditioner_ = make_distributed_preconditioner(grid, modulus, comm, threads);
    z_.assign(n, 0.0);
  }
}

DistributedBemSolver::~DistributedBemSolver() = default;

// Bytes a point of the slab, measured as bytes() / slab points with mpiexec -np 2 and 3 on 256^2 and 640 x
// 512 surfaces (periodic / not; docs/mpi.md "Memory a point"), with 10 % of margin: polonsky_keer 86 / 136,
// preconditioned_cg 116 / 217 (periodic on 2 ranks and more: the slab engine's two exchange buffers, 16 B,
// in place of FFTW-MPI's slab, 8 B, for each of the operator and the preconditioner; one thread a rank; in
// shared memory the engine holds one, 8 B, and the estimate keeps the larger).
// active_set: what it holds from solve to solve (the pressure, heights, displacement, the transform and both
// multipliers) 40 / 120, and during a solve either its work arrays (32, plus a transient selection array of
// the cold start, at most 8) or, before them, its coarse start: the first level of at most kGatherBound
// points whole on every rank (~100 B a point of that level, Coarse::bytes) and the levels on slabs (a quarter
// of the points each: at most a third of the finest level's kept and work).
std::size_t DistributedBemSolver::estimated_bytes(const Grid& grid, Index slab_points,
                                                  const BemSolverOptions& options) {
  const bool periodic = grid.periodic;
  const double slab = static_cast<double>(slab_points), points = static_cast<double>(grid.points());
  double bytes = 0;
  switch (options.solver) {
    case SolverKind::polonsky_keer:
      bytes = (periodic ? 95 : 150) * slab;
      break;
    case SolverKind::preconditioned_cg:
      bytes = (periodic ? 128 : 240) * slab;
      break;
    case SolverKind::active_set: {
      double gathered = points / 4;  // the coarse levels halve each side
      while (gathered > static_cast<double>(DistributedActiveSet::kGatherBound))
        gathered /= 4;
      const double kept = (periodic ? 44 : 132) * slab, work = 44 * slab;
      const double coarse = 100 * gathered + (kept + work) / 3;
      bytes = kept + std::max(work, coarse);
      break;
    }
  }
  return static_cast<std::size_t>(std::ceil(bytes)) + (1u << 20);  // and a MiB of plans and small arrays
}

std::size_t DistributedBemSolver::bytes() const {
  const std::size_t values = h_.capacity() + g_.capacity() + t_.capacity() + u_.capacity() + z_.capacity() +
                             q_[0].capacity() + q_[1].capacity();
  // The solution's pressure and gap, 16 B a point, made by write() after each solve: with active_set they
  // are freed when the next solve starts and made after it has freed its work arrays, so they count against
  // those (which are more, 32 B a point), not on top.
  const std::size_t solution = 2 * sizeof(double) * static_cast<std::size_t>(local_points_);
  if (active_set_)
    return sizeof(double) * values + std::max(active_set_->bytes(), active_set_->kept_bytes() + solution);
  return sizeof(double) * values + solution + (operator_ ? operator_->bytes() : 0) +
         (preconditioner_ ? preconditioner_->bytes() : 0);
}

void DistributedBemSolver::apply(const std::vector<double>& in, std::vector<double>& out) {
  operator_->apply(in.data(), out.data());
}

// g = s_new u - h (u = G q_new, in u_), the change of the pressure from s_old q_old, and the moments of the
// gap on the contact set. Each rank sums about a shift, the first gap in contact it meets, and the ranks'
// sums are combined exactly in rank order (Chan et al.) by the serial solver's own code for its threads'
// (cg::combine_moments; the same on every rank, so that every rank takes the same decisions).
cg::Moments DistributedBemSolver::gap_pass(const std::vector<double>& q_new, const std::vector<double>& q_old,
                                           double s_new, double s_old) {
  double change = 0, sum = 0, s1 = 0, s2 = 0, elastic = 0, shift = 0;
  bool has_shift = false;
  for (std::size_t i = 0; i < h_.size(); ++i) {
    const double p = s_new * q_new[i];
    change += std::abs(p - s_old * q_old[i]);
    sum += p;
    const double gv = s_new * u_[i] - h_[i];
    g_[i] = gv;
    if (p > 0) {
      if (!has_shift) {
        shift = gv;
        has_shift = true;
      }
      const double d = gv - shift;
      s1 += d;
      s2 += d * d;
      elastic += 1;
    }
  }
  const int ranks = size_of(comm_);
  const double mine[6] = {change, sum, elastic, shift, s1, s2};
  std::vector<double> all(static_cast<std::size_t>(6 * ranks));
  MPI_Allgather(mine, 6, MPI_DOUBLE, all.data(), 6, MPI_DOUBLE, comm_);
  // Each rank's sums as the serial solver's threads' partial sums, combined by the same code.
  std::vector<cg::Partial> parts(static_cast<std::size_t>(ranks));
  for (int r = 0; r < ranks; ++r) {
    cg::Partial& part = parts[static_cast<std::size_t>(r)];
    part.change = all[6 * r];
    part.sum = all[6 * r + 1];
    part.elastic = all[6 * r + 2];
    part.shift = all[6 * r + 3];
    part.s1 = all[6 * r + 4];
    part.s2 = all[6 * r + 5];
  }
  return cg::combine_moments<true>(parts);
}

// bem/solvers/polonsky_keer_solver.cpp's iterate<kLoad = true, kHard = false>, plain or preconditioned, pass
// by pass; the decisions between passes are the same code (bem/solvers/polonsky_keer_step.hpp).
void DistributedBemSolver::iterate(double total) {
  const double tolerance = options_.tolerance;
  const Index max_iterations = options_.max_iterations;
  const double self_response = operator_->self_response();
  const bool preconditioned = preconditioner_ != nullptr;
  const std::size_t n = h_.size();

  apply(q_[cur_], u_);
  cg::Moments moments = gap_pass(q_[cur_], q_[cur_], s_[cur_], s_[cur_]);

  double g_norm_old = 1, delta = 0, change = 0;  // delta = 0: the first step is steepest descent
  double rz_old = 1;                             // preconditioned: <r, z> of the last direction
  double entered = 0;                            // nodes that entered the set in the last update
  PolonskyKeerStep step;                         // the serial solver's criterion, damping and step lengths
  Index iteration = 0;
  bool converged = false;
  for (;;) {
    if (iteration > 0) {
      change = PolonskyKeerStep::relative_change(moments.change, moments.sum);
      if (PolonskyKeerStep::converged(change, tolerance, preconditioned, entered)) {
        converged = true;
        break;
      }
      step.observe(change);
    }
    if (iteration == max_iterations) break;
    if (options_.between_iterations) options_.between_iterations();
    if (moments.elastic == 0) throw Error("Polonsky-Keer: the contact set became empty");
    const std::vector<double>& q_cur = q_[cur_];
    const double s_cur = s_[cur_], gbar = moments.g_mean;

    // The direction on the contact set, and r = G t. Plain: t = g - gbar + beta t (PK eq. 11).
    // Preconditioned: z = the filtered residual g - gbar on the set, t = z - zbar + beta t
    // (bem/solvers/preconditioned_cg_solver.cpp).
    double beta = 0;
    double step_sums[5] = {0, 0, 0, 0, 0};  // sum (g - gbar) t, sum t, sum t^2, sum r on the set, t . r
    if (preconditioned) {
      for (std::size_t i = 0; i < n; ++i)
        u_[i] = q_cur[i] > 0 ? g_[i] - gbar : 0.0;
      double residual_sums[3] = {0, 0, 0};  // sum r, sum z, sum r z on the set
      for (std::size_t i = 0; i < n; ++i)
        residual_sums[0] += u_[i];
      preconditioner_->apply(u_.data(), z_.data());
      for (std::size_t i = 0; i < n; ++i) {
        const bool in = q_cur[i] > 0;
        z_[i] = in ? z_[i] : 0.0;
        residual_sums[1] += z_[i];
        residual_sums[2] += in ? (g_[i] - gbar) * z_[i] : 0.0;
      }
      sum_over_ranks(residual_sums, comm_);
      const double zbar = residual_sums[1] / moments.elastic;
      const double rz = residual_sums[2] - zbar * residual_sums[0];
      beta = delta > 0 && rz_old > 0 ? rz / rz_old : 0.0;
      rz_old = rz;
      for (std::size_t i = 0; i < n; ++i) {
        const bool in = q_cur[i] > 0;
        const double tv = in ? (z_[i] - zbar) + beta * t_[i] : 0.0;
        t_[i] = tv;
        step_sums[0] += in ? (g_[i] - gbar) * tv : 0.0;
        step_sums[1] += tv;
        step_sums[2] += tv * tv;
      }
    } else {
      beta = delta > 0 && g_norm_old > 0 ? moments.g_norm / g_norm_old : 0.0;
      g_norm_old = moments.g_norm;
      for (std::size_t i = 0; i < n; ++i) {
        const double gc = g_[i] - gbar;
        const double tv = q_cur[i] > 0 ? gc + beta * t_[i] : 0.0;
        t_[i] = tv;
        step_sums[0] += gc * tv;
        step_sums[1] += tv;
      }
    }
    apply(t_, u_);  // u_ holds r = G t until the next gap pass
    for (std::size_t i = 0; i < n; ++i) {
      step_sums[3] += q_cur[i] > 0 ? u_[i] : 0.0;
      step_sums[4] += t_[i] * u_[i];
    }
    sum_over_ranks(step_sums, comm_);
    const double gt = step_sums[0], t_sum = step_sums[1], tt = step_sums[2], r_sum = step_sums[3];
    // t . (r - rbar) on the contact set (t is zero elsewhere).
    const double tr = step_sums[4] - r_sum / moments.elastic * t_sum;
    const PolonskyKeerStep::Lengths lengths = step.lengths(gt, tr, tt, self_response, preconditioned);
    const double tau = lengths.tau, tau_enter = lengths.enter;

    // The update q = max(p - tau t, 0); nodes out of contact that the surface penetrates enter with
    // -tau_enter g (PK eq. 14). Then the load imposed by rescaling, and the next gap.
    const int next = 1 - cur_;
    std::vector<double>& q_next = q_[next];
    double update_sums[2] = {0, 0};  // sum q, nodes that entered
    for (std::size_t i = 0; i < n; ++i) {
      const double p = s_cur * q_cur[i];
      const double gc = g_[i] - gbar;
      const bool moved = (p <= 0) & (gc < 0);
      const double v = moved ? -tau_enter * gc : std::max(p - tau * t_[i], 0.0);
      q_next[i] = v;
      update_sums[0] += v;
      update_sums[1] += moved ? 1.0 : 0.0;
    }
    sum_over_ranks(update_sums, comm_);
    const double s_new = update_sums[0] > 0 ? total / update_sums[0] : 0.0;
    apply(q_next, u_);
    moments = gap_pass(q_next, q_cur, s_new, s_cur);
    cur_ = next;
    s_[cur_] = s_new;
    entered = update_sums[1];
    delta = entered > 0 ? 0 : 1;
    ++iteration;
  }
  iterations_ = iteration;
  change_ = change;
  converged_ = converged;
  separation_ = -moments.g_mean;  // the flat, from the mean gap on the contact set
}

// The active-set method from the serial solver's start (bem/solvers/active_set_solver.cpp): warm, the
// previous pressure scaled to the load (PressureState::begin_load); cold, its nested coarse start.
void DistributedBemSolver::solve_active_set(double mean_pressure, double total) {
  // The pressure scaled in place and solved in place (no second copy of it).
  std::vector<double>& q = q_[cur_];
  if (warm_) {
    double sum = 0;
    for (const double v : q)
      sum += v;
    const double s = total / sum_over_ranks(sum, comm_);
    for (double& v : q)
      v = s * v;
  }
  const ActiveSetOutcome outcome =
      active_set_->solve({.load_control = true,
                          .mean_pressure = mean_pressure,
                          .hardness = options_.hardness.value_or(std::numeric_limits<double>::infinity())},
                         options_.tolerance, options_.max_iterations, warm_, q, options_.between_iterations);
  s_[cur_] = 1;
  separation_ = outcome.separation;  // the gap is g + d
  iterations_ = outcome.iterations;
  change_ = outcome.change;
  converged_ = outcome.converged;
}

void DistributedBemSolver::write() {
  const Slab& slab = slab_;
  solution_.pressure.resize(slab.count, grid_.nx);
  solution_.gap.resize(slab.count, grid_.nx);
  const std::vector<double>& q = q_[cur_];
  // As the serial solver counts them (bem/solvers/pressure_state.cpp): nodes at p >= H are plastic, in
  // contact, their gap 0 and left out of the residual (the surface flowed to fit the flat there).
  const double hardness = options_.hardness.value_or(std::numeric_limits<double>::infinity());
  double residual = 0, counts[2] = {0, 0};  // contact, plastic
  // G p - h: the PK solvers' g_, active_set's from its own fields (-h after a zero load).
  auto minus_heights = [&](std::size_t i) {
    if (!active_set_) return g_[i];
    return unloaded_ ? -active_set_->heights()[i] : active_set_->displacement_minus_height(i);
  };
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double p = s_[cur_] * q[i];
    solution_.pressure.data()[i] = p;
    const double gap = minus_heights(i) + separation_;
    if (!(p > 0)) {
      solution_.gap.data()[i] = gap;
    } else {
      solution_.gap.data()[i] = 0;
      counts[0] += 1;
      if (p >= hardness)
        counts[1] += 1;
      else
        residual = std::max(residual, std::abs(gap));
    }
  }
  sum_over_ranks(counts, comm_);
  solution_.contact_points = static_cast<Index>(counts[0]);
  solution_.plastic_points = static_cast<Index>(counts[1]);
  solution_.residual = max_over_ranks(residual, comm_) / (height_range_ > 0 ? height_range_ : 1.0);
  solution_.separation = separation_;
  solution_.iterations = iterations_;
  solution_.change = change_;
  // As the serial solver: converged only with a small complementarity residual too (bem/bem_solver.hpp).
  solution_.converged = converged_ && solution_.residual <= residual_bound(options_.tolerance);
}

const DistributedContactSolution& DistributedBemSolver::solve(Real mean_pressure) {
  if (!(std::isfinite(mean_pressure) && mean_pressure >= 0))
    throw Error("Polonsky-Keer: the mean pressure must be finite and >= 0 Pa, got " +
                std::to_string(mean_pressure));
  solution_ = DistributedContactSolution{};
  solution_.mean_pressure = mean_pressure;
  if (mean_pressure == 0) {
    // No load, no contact: the flat rests at the highest point (as the serial solver).
    const std::vector<double>& h = active_set_ ? active_set_->heights() : h_;
    const double local_max =
        h.empty() ? -std::numeric_limits<double>::infinity() : *std::max_element(h.begin(), h.end());
    separation_ = max_over_ranks(local_max, comm_);
    std::fill(q_[cur_].begin(), q_[cur_].end(), 0.0);
    if (!active_set_)
      for (std::size_t i = 0; i < h_.size(); ++i)
        g_[i] = -h_[i];
    unloaded_ = true;
    iterations_ = 0;
    change_ = 0;
    converged_ = true;
    warm_ = false;
    write();
    return solution_;
  }
  // The start after a previous load as one process chooses it (bem/solvers/load_stepping.hpp): forced, or
  // the one the solver declares (active_set: cold, its nested coarse start, from 512^2), so that the
  // iterations stay those of one process.
  if (load_path_start(options_, grid_) == LoadPathStart::cold) warm_ = false;
  unloaded_ = false;
  const double total = mean_pressure * static_cast<double>(grid_.points());
  if (active_set_) {
    // (its start is its own: solve_active_set)
  } else if (warm_) {  // the previous pressure scaled to the new load
    double sum = 0;
    for (const double v : q_[cur_])
      sum += v;
    s_[cur_] = total / sum_over_ranks(sum, comm_);
  } else {  // the uniform pressure
    std::fill(q_[cur_].begin(), q_[cur_].end(), 1.0);
    s_[cur_] = mean_pressure;
  }
  try {
    if (active_set_)
      solve_active_set(mean_pressure, total);
    else
      iterate(total);
  } catch (...) {
    warm_ = false;
    throw;
  }
  warm_ = true;
  write();
  if (!solution_.converged && options_.warning)
    options_.warning(std::string(active_set_ ? "distributed active_set" : "distributed Polonsky-Keer") +
                     " did not converge at P/A0 = " + std::to_string(mean_pressure) + " in " +
                     std::to_string(iterations_) + " iterations (gap on the contact set " +
                     std::to_string(solution_.residual) + " of the height range); the result is marked " +
                     "converged = false");
  return solution_;
}

}  // namespace contactbench::mpi
