// The elastic-perfectly plastic BEM along a load path that goes up and down (BemSolverOptions::
// keep_plastic_deformation; docs/solvers.md "Hardness", "Unloading and reloading"; docs/theory.md section
// 6.7): the surface keeps the plastic deformation (heights lowered by the overlap where p = H), unloading is
// elastic, and reloading to a load already reached gives back its state (shakedown). On a sphere first (the
// onset of yield at Hertz's p0 = H), then on a rough surface, with every solver.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "contact_shapes.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/generation.hpp"
#include "each_solver.hpp"
#include "reference_solutions.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

class PlasticCycle : public EachSolver {};

constexpr Real kTolerance = 1e-10;  // of every solve here

// A reloaded state solves the same problem as the first (docs/theory.md section 6.7), so the two differ only
// at nodes whose pressure is within the solver's tolerance of 0, where the sign is the round-off's: a few
// edge nodes at most; allow 1 % of the contact count (the scene test on surface A at 32^2 and the surface A
// cycle at 256^2, results/plasticity, gave identical counts).
constexpr Real kReloadAreaShare = 0.01;
// The reloaded pressure against the first: two solutions of one problem, each to the tolerance 1e-10 in the
// relative pressure change and a residual within 100 x that (bem_solver.hpp); allow 1e-6 in relative L2,
// far above those and far below the change a lost plastic node makes (H over the norm, about 1e-2 here).
constexpr Real kReloadPressure = 1e-6;

Surface rough_surface(Index n) {
  const Grid grid{.nx = n, .ny = n, .lx = 100e-6, .ly = 100e-6, .periodic = true};
  return generate_surface(grid, paper::surface_a(), 7);
}

Real relative_l2(const HeightMap& a, const HeightMap& b) {
  return (a - b).matrix().norm() / b.matrix().norm();
}

TEST_P(PlasticCycle, SphereYieldsWhereHertzPeakReachesTheHardness) {
  // Hertz's peak pressure p0 = (6 P E*^2/(pi^3 R^2))^(1/3) reaches H at P_y = pi^3 R^2 H^3/(6 E*^2) (Johnson
  // 1985, eq. 4.23 with p0 = H: the capped model's first yield). H = 0.9 of the peak pressure at a = 24
  // pixels: at 0.85 P_y (p0 = 0.947 H) no node is plastic, at 1.2 P_y (p0 = 1.063 H) some are. The discrete
  // peak differs from Hertz's by the discretisation of a contact about 20 pixels in radius; the 5 % and 6 %
  // margins leave room for that while still placing yield at p0 = H.
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3;
  const reference::HertzSphere hertz{.radius = radius, .modulus = testing::kPaperModulus};
  const Real hardness = 0.9 * hertz.peak_pressure(hertz.load_of_contact_radius(24 * dx));
  const Real yield_load = std::pow(pi, 3) * radius * radius * std::pow(hardness, 3) /
                          (6 * testing::kPaperModulus * testing::kPaperModulus);
  EXPECT_NEAR(hertz.peak_pressure(yield_load), hardness, 1e-12 * hardness);  // the formula, checked
  const Surface surface = sphere(n, dx, radius);
  const Real area = surface.grid().nominal_area();
  for (const auto& [factor, plastic] : {std::pair{0.85, false}, std::pair{1.2, true}}) {
    BemSolver solver(surface, testing::kPaperModulus,
                     {.tolerance = kTolerance, .hardness = hardness, .solver = GetParam()});
    const ContactSolution& s = solver.solve(factor * yield_load / area);
    ASSERT_TRUE(s.converged) << factor;
    EXPECT_EQ(s.plastic_points > 0, plastic) << factor << ": peak " << s.pressure.maxCoeff() / hardness;
  }
}

TEST_P(PlasticCycle, SphereUnloadsOnItsFlattenedCapAndReloadsToTheSameState) {
  // Load a sphere to twice its yield load, unload to half of it, reload. The flattened cap (a flat of the
  // plastic core's size) stays: unloading to a load meets more area than loading to it did, and reloading
  // gives the loaded state again.
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3;
  const reference::HertzSphere hertz{.radius = radius, .modulus = testing::kPaperModulus};
  const Real hardness = 0.7 * hertz.peak_pressure(hertz.load_of_contact_radius(24 * dx));
  const Surface surface = sphere(n, dx, radius);
  const Real area = surface.grid().nominal_area();
  const Real top = hertz.load_of_contact_radius(24 * dx) / area, low = 0.5 * top;
  BemSolver solver(surface, testing::kPaperModulus,
                   {.tolerance = kTolerance,
                    .hardness = hardness,
                    .keep_plastic_deformation = true,
                    .solver = GetParam()});
  const ContactSolution up_low = solver.solve(low);
  const ContactSolution up_top = solver.solve(top);
  const ContactSolution down_low = solver.solve(low);
  const ContactSolution again_top = solver.solve(top);
  for (const ContactSolution* s : {&up_low, &up_top, &down_low, &again_top})
    ASSERT_TRUE(s->converged);
  ASSERT_GT(up_top.plastic_points, 0);
  EXPECT_EQ(down_low.plastic_points, 0);  // unloading is elastic
  EXPECT_GT(down_low.contact_points, up_low.contact_points);
  // The residual topography: the apex lowered, and no point raised.
  const HeightMap lowered = surface.centred().heights() - solver.surface().heights();
  EXPECT_GE(lowered.minCoeff(), 0);
  EXPECT_GT(lowered(n / 2, n / 2), 0);
  EXPECT_NEAR(static_cast<Real>(again_top.contact_points), static_cast<Real>(up_top.contact_points),
              kReloadAreaShare * static_cast<Real>(up_top.contact_points));
  EXPECT_LT(relative_l2(again_top.pressure, up_top.pressure), kReloadPressure);
}

TEST_P(PlasticCycle, RoughSurfaceShakesDownOnReloading) {
  // Surface A on 64^2, H at 0.3 of the largest elastic pressure at the top load (a few % of the contact
  // plastic). Path: up through three loads, down to the first, up again to the top. Reloading to a load
  // gives the first loading's area and pressure (the deformed surface's elastic solution is the loaded
  // state), and the second reloading changes the surface no more (the overlap is zero to the tolerance).
  const Surface surface = rough_surface(64);
  const Real top = 0.02 * testing::kPaperModulus * 0.05;  // P/A0: a few % of contact
  BemSolver elastic(surface, testing::kPaperModulus, {.tolerance = kTolerance, .solver = GetParam()});
  const Real hardness = 0.3 * elastic.solve(top).pressure.maxCoeff();
  BemSolver solver(surface, testing::kPaperModulus,
                   {.tolerance = kTolerance,
                    .hardness = hardness,
                    .keep_plastic_deformation = true,
                    .solver = GetParam()});
  const std::vector<Real> path{0.25 * top, 0.5 * top, top, 0.5 * top, 0.25 * top, 0.5 * top, top};
  std::vector<ContactSolution> states;
  for (const Real load : path) {
    states.push_back(solver.solve(load));
    ASSERT_TRUE(states.back().converged) << load / top << ": residual " << states.back().residual;
  }
  ASSERT_GT(states[2].plastic_points, 0);
  const HeightMap residual = solver.surface().heights();
  for (const auto& [first, again] : {std::pair{1, 5}, std::pair{2, 6}}) {
    const ContactSolution& a = states[static_cast<std::size_t>(first)];
    const ContactSolution& b = states[static_cast<std::size_t>(again)];
    // Loading to 0.5 top happened before the plastic flow at the top load: the unloading branch meets the
    // flattened summits, so its area is at least the first loading's, and reloading to the top gives it back.
    if (first == 2) {
      EXPECT_NEAR(static_cast<Real>(b.contact_points), static_cast<Real>(a.contact_points),
                  kReloadAreaShare * static_cast<Real>(a.contact_points));
      EXPECT_LT(relative_l2(b.pressure, a.pressure), kReloadPressure);
    } else {
      EXPECT_GE(b.contact_points, a.contact_points);
    }
  }
  // Unloading creates no plastic point; the second loading to the top overlaps nothing anew (every overlap
  // below the complementarity residual the solve accepts, residual_bound x the height range).
  EXPECT_EQ(states[3].plastic_points, 0);
  EXPECT_EQ(states[4].plastic_points, 0);
  const Real range = surface.heights().maxCoeff() - surface.heights().minCoeff();
  EXPECT_LE(states[6].plastic_overlap.maxCoeff(), residual_bound(kTolerance) * range);
  // The residual topography lies nowhere above the surface, and below it only where the surface flowed.
  const HeightMap lowered = surface.centred().heights() - residual;
  EXPECT_GE(lowered.minCoeff(), 0);
  Index lowered_points = 0;
  for (Index i = 0; i < lowered.size(); ++i)
    lowered_points += lowered.data()[i] > 0;
  EXPECT_GT(lowered_points, 0);
  EXPECT_LE(lowered_points, states[2].contact_points);
}

TEST_P(PlasticCycle, WithoutKeepingTheDeformationEveryLoadSeesTheGivenSurface) {
  // The default: the surface stays as given, so a load solved after a higher one equals its cold solve.
  const Surface surface = rough_surface(64);
  const Real top = 0.02 * testing::kPaperModulus * 0.05;
  BemSolver elastic(surface, testing::kPaperModulus, {.tolerance = kTolerance, .solver = GetParam()});
  const Real hardness = 0.3 * elastic.solve(top).pressure.maxCoeff();
  const BemSolverOptions options{.tolerance = kTolerance, .hardness = hardness, .solver = GetParam()};
  BemSolver stepped(surface, testing::kPaperModulus, options);
  stepped.solve(top);
  const ContactSolution after = stepped.solve(0.5 * top);
  BemSolver cold(surface, testing::kPaperModulus, options);
  const ContactSolution& fresh = cold.solve(0.5 * top);
  ASSERT_TRUE(after.converged && fresh.converged);
  EXPECT_EQ(stepped.surface().heights().matrix(), surface.centred().heights().matrix());
  EXPECT_NEAR(static_cast<Real>(after.contact_points), static_cast<Real>(fresh.contact_points),
              kReloadAreaShare * static_cast<Real>(fresh.contact_points));
}

CB_FOR_EACH_SOLVER(PlasticCycle);

}  // namespace
}  // namespace contactbench
