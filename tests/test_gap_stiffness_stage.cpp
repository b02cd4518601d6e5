// The stage's stiffness path (bem/contact_stiffness.hpp ContactStiffnessSolver: plans made once, the stage
// tolerance kStageStiffnessTolerance) against the one-state path it replaced (contact_stiffness: from x = 0,
// relative residual 1e-10), on rough surfaces along a load path (docs/solvers.md, "The stiffness solve").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_stiffness.hpp"
#include "contactbench/core/generation.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

// The converged pressures of surface A's spectrum (seed `seed`, 128^2) at six loads P/(E* A0) = 1e-3 ...
// 2e-2.
std::vector<HeightMap> load_path(const Grid& grid, unsigned seed) {
  const Surface surface = generate_surface(grid, paper::surface_a(), seed);
  BemSolver solver(surface, testing::kPaperModulus, {.tolerance = 1e-10});
  std::vector<HeightMap> pressures;
  for (int k = 0; k < 6; ++k) {
    const ContactSolution& s = solver.solve(1e-3 * std::pow(20.0, k / 5.0) * testing::kPaperModulus);
    EXPECT_TRUE(s.converged);
    pressures.push_back(s.pressure);
  }
  return pressures;
}

class StageStiffness : public ::testing::TestWithParam<bool> {};  // the grid's periodicity

TEST_P(StageStiffness, GivesTheStiffnessOfTheTightOneStateSolve) {
  const bool periodic = GetParam();
  const Grid grid{.nx = 128, .ny = 128, .lx = 100e-6, .ly = 100e-6, .periodic = periodic};
  for (const unsigned seed : {7u, 8u}) {
    const std::vector<HeightMap> pressures = load_path(grid, seed);
    ContactStiffnessSolver stage(grid, testing::kPaperModulus, std::nullopt, 1,
                                 {.tolerance = kStageStiffnessTolerance});
    for (std::size_t k = 0; k < pressures.size(); ++k) {
      const ContactStiffness tight = contact_stiffness(grid, testing::kPaperModulus, pressures[k]);
      const ContactStiffness fast = stage.solve(pressures[k]);
      ASSERT_TRUE(tight.converged && fast.converged);
      EXPECT_LT(fast.iterations, tight.iterations);
      // The comparison needs K to 1e-4 relative (the BEM's own grid error is of order 1 %); the energy
      // estimate's error is quadratic in the residual (docs/theory.md 12.2), so the stage tolerance 1e-5
      // must give 1e-7 with room (measured: see the property).
      const Real difference = std::abs(fast.stiffness / tight.stiffness - 1);
      char measured[32];
      std::snprintf(measured, sizeof measured, "%.3g", difference);
      RecordProperty("seed_" + std::to_string(seed) + "_load_" + std::to_string(k + 1) + "_difference",
                     measured);
      EXPECT_LT(difference, 1e-7) << "seed " << seed << ", load " << k + 1;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Boundaries, StageStiffness, ::testing::Values(true, false),
                         [](const auto& info) { return info.param ? "periodic" : "nonperiodic"; });

}  // namespace
}  // namespace contactbench
