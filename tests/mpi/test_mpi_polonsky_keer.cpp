// The distributed Polonsky-Keer solver against the serial one (bem/bem_solver.hpp) on the same surface.
#include <gtest/gtest.h>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/mpi/distributed_bem_solver.hpp"
#include "mpi_fixtures.hpp"

namespace contactbench::mpi {
namespace {

constexpr Real kPkModulus = 1e11;
// The two solvers take the same steps; only the round-off of the operator (~1e-15 relative,
// test_mpi_half_space) and of the sums (other orders) differs: measured 4e-16..3e-15 of the peak pressure on
// these loads, on 1 to 3 ranks; 1e-12 as the issue asks. (A harder load of the non-periodic surface, 0.06 E*
// gbar, came to 5e-14..8e-13: its last iterations already feel the round-off.) At the scenes' tolerance,
// 1e-8. Much tighter, the last iterations run at the operator's round-off floor, where any reordering of the
// sums steers them (measured on the non-periodic case at 1e-10: the trajectories part once the change is
// ~1e-8 and end one iteration and 4e-11 of the peak pressure apart, within what that tolerance promises;
// bem/solvers/constrained_cg_kernels.hpp says the same of different thread counts).
constexpr double kPkPressureTolerance = 1e-12;

BemSolverOptions options_for(SolverKind solver) {
  BemSolverOptions options;
  options.solver = solver;
  options.tolerance = 1e-8;
  return options;
}

BemSolverOptions plain() {
  return options_for(SolverKind::polonsky_keer);
}

// Solves the loads in order with both solvers (warm starts), and compares each load's result on rank 0.
void expect_same_solutions(const Surface& surface, const std::vector<double>& slope_fractions,
                           const BemSolverOptions& options) {
  const Grid& grid = surface.grid();
  const Slab slab = slab_of(grid, MPI_COMM_WORLD);
  DistributedBemSolver distributed(grid, testing::rows_of(surface.heights(), slab), kPkModulus,
                                   MPI_COMM_WORLD, options);
  BemSolver serial(surface, kPkModulus, options);
  const Real slope = spectral_moments(surface).rms_gradient();
  for (const double fraction : slope_fractions) {
    const Real load = fraction * kPkModulus * slope;  // about 2 * fraction of the area in contact
    const DistributedContactSolution& d = distributed.solve(load);
    const HeightMap pressure = gather_to_root(d.pressure, slab, MPI_COMM_WORLD);
    const HeightMap gap = gather_to_root(d.gap, slab, MPI_COMM_WORLD);
    const ContactSolution& s = serial.solve(load);
    if (rank_of(MPI_COMM_WORLD) != 0) continue;
    const std::string what = std::string(solver_name(options.solver)) + ", " + std::to_string(grid.nx) +
                             " x " + std::to_string(grid.ny) +
                             (grid.periodic ? " periodic" : " non-periodic") + ", load " +
                             std::to_string(load);
    EXPECT_TRUE(s.converged && d.converged) << what;
    EXPECT_EQ(d.iterations, s.iterations) << what;
    EXPECT_EQ(d.contact_points, s.contact_points) << what;
    if (fraction == 0) {  // no load: nothing touches (and the next load starts afresh)
      EXPECT_TRUE((pressure == 0).all() && (s.pressure.array() == 0).all()) << what;
      continue;
    }
    EXPECT_GT(s.contact_points, 0) << what;
    EXPECT_LT(testing::relative_difference(pressure, s.pressure), kPkPressureTolerance) << what;
    // The gap and the flat's height: differences of u - h, so relative to the surface's height range.
    const Real range = surface.heights().maxCoeff() - surface.heights().minCoeff();
    EXPECT_LT((gap - s.gap).abs().maxCoeff(), kPkPressureTolerance * range) << what;
    EXPECT_NEAR(d.separation, s.separation, kPkPressureTolerance * range) << what;
    EXPECT_NEAR(d.residual, s.residual, 1e-9) << what;
  }
}

Surface periodic_surface() {
  return generate_surface({.nx = 64, .ny = 48, .lx = 1e-4, .ly = 0.75e-4, .periodic = true},
                          {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 4);
}

Surface non_periodic_surface() {
  return generate_surface({.nx = 40, .ny = 33, .lx = 1e-4, .ly = 0.8e-4, .periodic = true},
                          {.sigma = 1e-6, .hurst = 0.8, .qr = 1e5, .qs = std::nullopt}, 8)
      .with_periodic(false);
}

TEST(DistributedBemSolver, TakesTheSerialStepsOnAPeriodicSurface) {
  expect_same_solutions(periodic_surface(), {0.01, 0.03, 0.08}, plain());
}

TEST(DistributedBemSolver, TakesTheSerialStepsOnANonPeriodicSurface) {
  expect_same_solutions(non_periodic_surface(), {0.02, 0.045}, plain());
}

TEST(DistributedPreconditionedCg, TakesTheSerialStepsOnAPeriodicSurface) {
  expect_same_solutions(periodic_surface(), {0.01, 0.03, 0.08}, options_for(SolverKind::preconditioned_cg));
}

TEST(DistributedPreconditionedCg, TakesTheSerialStepsOnANonPeriodicSurface) {
  expect_same_solutions(non_periodic_surface(), {0.02, 0.045}, options_for(SolverKind::preconditioned_cg));
}

TEST(DistributedPreconditionedCg, IsNotThePlainIteration) {
  // The comparisons above would pass if both solvers ignored options.solver; the filter must show.
  const Surface surface = periodic_surface();
  const Slab slab = slab_of(surface.grid(), MPI_COMM_WORLD);
  const Real load = 0.01 * kPkModulus * spectral_moments(surface).rms_gradient();
  DistributedBemSolver plain_solver(surface.grid(), testing::rows_of(surface.heights(), slab), kPkModulus,
                                    MPI_COMM_WORLD, plain());
  DistributedBemSolver filtered(surface.grid(), testing::rows_of(surface.heights(), slab), kPkModulus,
                                MPI_COMM_WORLD, options_for(SolverKind::preconditioned_cg));
  EXPECT_LT(filtered.solve(load).iterations, plain_solver.solve(load).iterations);
}

// The default solver through the same interface: its first load from its own start, the next ones
// warm-started from the previous pressure scaled to the load, as the serial solver (the method itself against
// the serial one: test_mpi_active_set.cpp).
TEST(DistributedActiveSetSolver, TakesTheSerialStepsOnAPeriodicSurface) {
  expect_same_solutions(periodic_surface(), {0.01, 0.03, 0.08}, options_for(SolverKind::active_set));
}

TEST(DistributedActiveSetSolver, TakesTheSerialStepsOnANonPeriodicSurface) {
  expect_same_solutions(non_periodic_surface(), {0.02, 0.045}, options_for(SolverKind::active_set));
}

TEST(DistributedActiveSetSolver, TakesTheSerialStepsFromTheNestedCoarseStart) {
  // 128^2: the first load from a coarse level of 64^2, then warm; a zero load between forgets the start.
  const Surface surface = generate_surface({.nx = 128, .ny = 128, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                                           {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 5);
  expect_same_solutions(surface, {0.01, 0.03, 0.0, 0.02}, options_for(SolverKind::active_set));
}

TEST(DistributedActiveSetSolver, TakesTheSerialStepsWithEveryLoadCold) {
  // The start active_set declares from 512^2 on (bem/solvers/active_set_solver.cpp: each load from its
  // nested coarse start), forced here on 128^2 to stay fast: the distributed solver must go cold where one
  // process does, or the iterations part (a warm start takes other steps).
  const Surface surface = generate_surface({.nx = 128, .ny = 128, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                                           {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 5);
  BemSolverOptions options = options_for(SolverKind::active_set);
  options.load_path = LoadPathStart::cold;
  expect_same_solutions(surface, {0.01, 0.03, 0.02}, options);
}

TEST(DistributedBemSolver, ZeroLoadTouchesNothing) {
  const Surface surface = generate_surface({.nx = 32, .ny = 32, .lx = 1e-4, .ly = 1e-4, .periodic = true},
                                           {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 2);
  const Slab slab = slab_of(surface.grid(), MPI_COMM_WORLD);
  DistributedBemSolver solver(surface.grid(), testing::rows_of(surface.heights(), slab), kPkModulus,
                              MPI_COMM_WORLD, plain());
  const DistributedContactSolution& s = solver.solve(0);
  EXPECT_EQ(s.contact_points, 0);
  EXPECT_TRUE((s.pressure == 0).all());
  EXPECT_NEAR(s.separation, surface.centred().heights().maxCoeff(), 1e-15);
}

// The preflight's estimate (DistributedBemSolver::estimated_bytes) bounds what each rank then holds, and not
// by more than twice (plus the MiB it adds for plans): an estimate that lost a field would fail the first,
// one that refused solves that fit the second. On grids whose coarse levels are gathered (256^2) and on slabs
// (640 x 512, its first coarse level 320 x 256 above the gather bound).
TEST(DistributedBemSolver, EstimatesItsMemoryBeforeAllocating) {
  for (const bool periodic : {true, false})
    for (const Index nx : {256, 640}) {
      const Grid grid{.nx = nx, .ny = nx == 256 ? 256 : 512, .lx = 1e-4, .ly = 1e-4, .periodic = periodic};
      const Slab slab = slab_of(grid, MPI_COMM_WORLD);
      const HeightMap local = testing::rows_of(testing::test_field(grid.nx, grid.ny, 3), slab);
      for (const SolverKind kind :
           {SolverKind::polonsky_keer, SolverKind::preconditioned_cg, SolverKind::active_set}) {
        BemSolverOptions options = options_for(kind);
        options.max_iterations = 3;  // what is held, not the solution: a few iterations of a light load
        DistributedBemSolver solver(grid, local, kPkModulus, MPI_COMM_WORLD, options);
        // After a cold solve: active_set makes its coarse levels for the cold start only, so bytes() (the
        // most held at once) knows their peak once they have run.
        solver.solve(1e-4 * kPkModulus);
        const std::size_t held = solver.bytes();
        const std::size_t estimate = DistributedBemSolver::estimated_bytes(grid, slab.points(), options);
        EXPECT_GE(estimate, held) << grid.nx << " x " << grid.ny << (periodic ? " periodic" : "")
                                  << " solver " << static_cast<int>(kind);
        EXPECT_LE(estimate, 2 * held + (1u << 20))
            << grid.nx << " x " << grid.ny << (periodic ? " periodic" : "") << " solver "
            << static_cast<int>(kind);
      }
    }
}

TEST(DistributedBemSolver, RefusesWhatIsNotDistributedYetNamingIt) {
  const Grid grid{.nx = 16, .ny = 16, .lx = 1e-4, .ly = 1e-4, .periodic = true};
  const HeightMap local = HeightMap::Zero(slab_of(grid, MPI_COMM_WORLD).count, grid.nx);
  BemSolverOptions options = plain();
  options.hardness = 1e9;
  try {
    DistributedBemSolver solver(grid, local, kPkModulus, MPI_COMM_WORLD, options);
    ADD_FAILURE() << "a hardness was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hardness"), std::string::npos) << e.what();
  }
  options = plain();
  options.single_precision = true;
  options.tolerance = 1e-6;
  EXPECT_THROW(DistributedBemSolver(grid, local, kPkModulus, MPI_COMM_WORLD, options), Error);
}

}  // namespace
}  // namespace contactbench::mpi
