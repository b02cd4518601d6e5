// The contact stiffness K = -dP/dd of the BEM (bem/contact_stiffness.hpp; docs/theory.md section 12.2)
// against its analytic limits, a flat punch and Hertz (Sneddon: dP/dd = 2 E* a), and against finite
// differences along the load path of a rough surface.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "contact_shapes.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_stiffness.hpp"
#include "contactbench/core/generation.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

// The stiffness of a flat-ended punch is that of its face held in contact: a pressure field positive on a
// pixelated disc of `radius` pixels (its values do not matter, only the set). Returns K A0 / (2 E* a), a the
// radius of the disc's area.
Real punch_stiffness_ratio(Index radius) {
  const Index n = 4 * radius;
  const Real dx = 1e-6;
  const Grid grid{.nx = n, .ny = n, .lx = n * dx, .ly = n * dx, .periodic = false};
  HeightMap pressure = HeightMap::Zero(n, n);
  for (Index iy = 0; iy < n; ++iy)
    for (Index ix = 0; ix < n; ++ix)
      if (std::pow(ix - n / 2, 2) + std::pow(iy - n / 2, 2) <= std::pow(static_cast<Real>(radius), 2))
        pressure(iy, ix) = 1;
  const Real a = std::sqrt((pressure > 0).count() * dx * dx / pi);
  const ContactStiffness k = contact_stiffness(grid, testing::kPaperModulus, pressure);
  EXPECT_TRUE(k.converged);
  return k.stiffness * grid.nominal_area() / (2 * testing::kPaperModulus * a);
}

TEST(ContactStiffness, FlatPunchIsSneddonsTwoEstarA) {
  // Piecewise-constant pressures on a pixelated disc: the edge's square-root singularity is resolved to a
  // pixel, so the stiffness converges as the radius grows. 1 % at 10 pixels and beyond (the bound);
  // measured: see the EXPECTs' messages (docs/theory.md section 12.2).
  for (const Index radius : {10, 20}) {
    const Real ratio = punch_stiffness_ratio(radius);
    RecordProperty("ratio_radius_" + std::to_string(radius), std::to_string(ratio));
    EXPECT_NEAR(ratio, 1, 0.01) << "radius " << radius << " pixels: K A0/(2 E* a) = " << ratio;
  }
}

TEST(ContactStiffness, HertzIsTwoEstarA) {
  // Hertz: P = (4/3) E* R^(1/2) delta^(3/2), so dP/ddelta = 2 E* R^(1/2) delta^(1/2) = 2 E* a, the stiffness
  // of a flat punch of the contact radius (the edge pressure is 0, so the growth of the contact adds nothing
  // to first order). A load giving a = 15 pixels; judged against the Hertz radius of the load, 1 %.
  const Index n = 128;
  const Real dx = 1e-6, radius = 1e-3;
  const Real a = 15 * dx;
  const Real load = 4 * testing::kPaperModulus * a * a * a / (3 * radius);
  const Surface sphere = sphere_cap(n, n, dx, radius);
  BemSolver solver(sphere, testing::kPaperModulus, {.tolerance = 1e-10});
  const ContactSolution& s = solver.solve(load / sphere.grid().nominal_area());
  ASSERT_TRUE(s.converged);
  const ContactStiffness k = contact_stiffness(sphere.grid(), testing::kPaperModulus, s.pressure);
  ASSERT_TRUE(k.converged);
  const Real ratio = k.stiffness * sphere.grid().nominal_area() / (2 * testing::kPaperModulus * a);
  RecordProperty("ratio", std::to_string(ratio));
  EXPECT_NEAR(ratio, 1, 0.01) << "K A0/(2 E* a) = " << ratio;
}

TEST(ContactStiffness, LinearisedResponseMatchesFiniteDifferencesAlongTheLoadPath) {
  // The paper's surface A spectrum, 128^2, periodic: two loads 1 % apart. The secant (P2 - P1)/(d1 - d2)
  // against the mean of the two linearised stiffnesses. K grows about in proportion to P (K ~ P/u0 at small
  // loads), so over the step it changes by about 1 %; the secant and the mean of the end tangents then differ
  // by a second-order term, well below 1e-3, plus the steps of the discrete contact set (a few nodes each):
  // 2 % bounds both with room.
  const Grid grid{.nx = 128, .ny = 128, .lx = 100e-6, .ly = 100e-6, .periodic = true};
  const Surface surface = generate_surface(grid, paper::surface_a(), 7);
  BemSolver solver(surface, testing::kPaperModulus, {.tolerance = 1e-12});
  const Real p1 = 0.01 * testing::kPaperModulus, p2 = 1.01 * p1;
  const ContactSolution first = solver.solve(p1);
  const ContactSolution second = solver.solve(p2);
  ASSERT_TRUE(first.converged && second.converged);
  const Real secant = (p2 - p1) / (first.separation - second.separation);
  const Real k1 = contact_stiffness(grid, testing::kPaperModulus, first.pressure).stiffness;
  const Real k2 = contact_stiffness(grid, testing::kPaperModulus, second.pressure).stiffness;
  RecordProperty("secant_over_tangents", std::to_string(secant / (0.5 * (k1 + k2))));
  EXPECT_NEAR(secant / (0.5 * (k1 + k2)), 1, 0.02)
      << "secant " << secant << ", tangents " << k1 << ", " << k2;
  // On a periodic grid d is the mean gap: the solution's own gap field says so (to round-off).
  EXPECT_NEAR(first.gap.mean(), first.separation, 1e-9 * first.separation);
}

TEST(ContactStiffness, NoContactIsZeroAndFullPeriodicContactUnbounded) {
  const Grid grid{.nx = 8, .ny = 8, .lx = 8e-6, .ly = 8e-6, .periodic = true};
  EXPECT_EQ(contact_stiffness(grid, testing::kPaperModulus, HeightMap::Zero(8, 8)).stiffness, 0);
  EXPECT_TRUE(
      std::isinf(contact_stiffness(grid, testing::kPaperModulus, HeightMap::Constant(8, 8, 1.0)).stiffness));
}

}  // namespace
}  // namespace contactbench
