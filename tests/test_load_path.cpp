// How a load after a previous one starts (LoadPathStart, bem/solver_registry.hpp; docs/solvers.md
// "Starts: load stepping"): every start gives the cold solves' answers, and the start each solver declares
// (SolverEntry::load_path) never costs more iterations along a load curve than solving each load cold.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/solver_registry.hpp"
#include "contactbench/bem/solvers/load_stepping.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "each_solver.hpp"
#include "test_constants.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

// Surface A of the paper (docs/theory.md section 2) on n x n points over 200 um, seeded.
Surface surface_a(Index n, std::uint64_t seed) {
  const Grid grid{.nx = n, .ny = n, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  return generate_surface(grid, paper::surface_a(), seed);
}

// The loads of a curve: contact about `low` % to `high` % (P/(E* A0) = pct/100 gbar/2, Persson's
// small-contact law), `count` log-spaced, increasing.
std::vector<Real> curve_loads(const Surface& surface, double low, double high, int count) {
  const Real unit = testing::kPaperModulus * spectral_moments(surface).rms_gradient() / 2;
  std::vector<Real> loads;
  for (int k = 0; k < count; ++k)
    loads.push_back(low * std::pow(high / low, k / double(count - 1)) / 100 * unit);
  return loads;
}

class LoadPath : public EachSolver {};

TEST_P(LoadPath, EveryStartGivesTheColdAnswers) {
  // Surface A on 128 x 128 points, periodic and not, four loads 1 % ... 30 % contact in increasing order,
  // each started as each LoadPathStart says, and each also solved by a new solver (cold). All stop at
  // 1e-12, where the existing warm-start tests (tests/test_bem_validation.cpp) compare too: the node counts
  // equal, the pressures within tolerance::solver_consistency of the peak (two solves of one problem at
  // 1e-12 differ by 1e-14..1e-11 of it).
  for (const bool periodic : {true, false}) {
    const Surface surface = surface_a(128, 11).with_periodic(periodic);
    const std::vector<Real> loads = curve_loads(surface, 1, 30, 4);
    std::vector<ContactSolution> cold;
    for (const Real load : loads) {
      BemSolver alone(surface, testing::kPaperModulus,
                      {.tolerance = 1e-12, .max_iterations = 20000, .solver = GetParam()});
      cold.push_back(alone.solve(load));
    }
    for (const LoadPathStart start :
         {LoadPathStart::scaled, LoadPathStart::extrapolated, LoadPathStart::cold, LoadPathStart::solver}) {
      BemSolver path(surface, testing::kPaperModulus,
                     {.tolerance = 1e-12, .max_iterations = 20000, .solver = GetParam(), .load_path = start});
      for (std::size_t k = 0; k < loads.size(); ++k) {
        const ContactSolution& s = path.solve(loads[k]);
        const std::string what = std::string(periodic ? "periodic" : "non-periodic") + ", " +
                                 std::string(load_path_start_name(start)) + ", load " + std::to_string(k);
        EXPECT_TRUE(s.converged) << what;
        EXPECT_EQ(s.contact_points, cold[k].contact_points) << what;
        EXPECT_LT((s.pressure - cold[k].pressure).abs().maxCoeff(),
                  tolerance::solver_consistency * cold[k].pressure.maxCoeff())
            << what;
      }
    }
  }
}

CB_FOR_EACH_SOLVER(LoadPath);

// The total iterations of `loads` solved in order by one solver that starts each load as `start` says.
// With a hardness, the pressure is capped at it.
Index curve_iterations(const Surface& surface, const std::vector<Real>& loads, SolverKind solver,
                       LoadPathStart start, std::optional<Real> hardness = std::nullopt) {
  constexpr int kThreads = 2;  // as the benchmark (bench/bench_load_path.cpp)
  BemSolver along(surface, testing::kPaperModulus,
                  {.tolerance = 1e-8,
                   .max_iterations = 20000,
                   .hardness = hardness,
                   .solver = solver,
                   .load_path = start},
                  kThreads);
  Index iterations = 0;
  for (const Real load : loads) {
    const ContactSolution& s = along.solve(load);
    EXPECT_TRUE(s.converged);
    iterations += s.iterations;
  }
  return iterations;
}

TEST(LoadPathDeclared, TheDefaultSolversCurveCostsNoMoreThanColdSolves) {
  // The default solver's declared start along a load curve where its old start, the last solution's
  // contact set (LoadPathStart::scaled), cost more than cold solves: surface A refined to 512 x 512,
  // non-periodic, ten loads 1 % ... 30 % contact, tolerance 1e-8 (the paper scenes'), as
  // bench/bench_load_path.cpp measures (there 275 warm against 267 cold iterations). Iteration counts are
  // deterministic for a fixed thread count and a seeded surface: no tolerance. The old start must cost more
  // here, so that this test fails if it were declared again.
  const Grid grid = paper::grid();
  const Surface surface =
      synthesize(grid, generate_coefficients(grid, paper::surface_a(), 1), 512, 512).with_periodic(false);
  const std::vector<Real> loads = curve_loads(surface, 1, 30, 10);
  const Index cold = curve_iterations(surface, loads, kDefaultSolver, LoadPathStart::cold);
  const Index declared = curve_iterations(surface, loads, kDefaultSolver, LoadPathStart::solver);
  EXPECT_LE(declared, cold);
  const Index old_warm = curve_iterations(surface, loads, kDefaultSolver, LoadPathStart::scaled);
  EXPECT_GT(old_warm, cold) << "the test surface no longer shows the old start's cost";
}

TEST(LoadPathDeclared, TheDefaultSolverStartsACappedCurveWarmOnEveryGrid) {
  // From 512^2 points the default solver starts an elastic load cold (the test above), but a capped one
  // from the last solution: its nested coarse start solves the elastic problem, far from the capped one.
  // The rule, then its reason on the benchmark's capped curve (bench_bem_solvers plastic rows: surface A,
  // H = 0.1 E*, ten loads 0.001 ... 0.01 E*, up to 5 % of A0 plastic), here at 256^2 to stay fast:
  // iteration counts are deterministic for a fixed thread count, so no tolerance; the cold curve must cost
  // more, so that this test fails if capped curves were declared cold.
  const Grid large{.nx = 512, .ny = 512, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  BemSolverOptions options{.solver = kDefaultSolver};
  EXPECT_EQ(load_path_start(options, large), LoadPathStart::cold);
  options.hardness = 0.1 * testing::kPaperModulus;
  EXPECT_EQ(load_path_start(options, large), LoadPathStart::scaled);

  const Surface surface = surface_a(256, 1);
  std::vector<Real> loads;
  for (int k = 1; k <= 10; ++k)
    loads.push_back(0.001 * k * testing::kPaperModulus);
  const Index cold = curve_iterations(surface, loads, kDefaultSolver, LoadPathStart::cold, options.hardness);
  const Index declared =
      curve_iterations(surface, loads, kDefaultSolver, LoadPathStart::solver, options.hardness);
  EXPECT_LT(declared, cold);
}

}  // namespace
}  // namespace contactbench
