// The Hertz-consistent plateau model's stiffness (theories/plateau_hertz.hpp, docs/theory.md section 12.5):
// K_H = 2 E* sqrt(A_H N / pi) / A0 against the secant of the model's own load curve, and given by the
// scene's method when the scene compares the stiffness.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <vector>

#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/theories/plateau_hertz.hpp"
#include "contactbench/theories/plateau_model.hpp"
#include "random_surface.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

using testing::random_surface;

// With exact levels the model's load is linear in the separation between two successive levels (the spots
// and area of the lower level hold there, theories/plateau_model.hpp), so the secant between two loads
// inside one such step is the model's dP/dz exactly. Tolerance 1e-8 relative: the separations differ by
// about half a level step (1e-9 to 1e-8 m here) out of magnitudes near 1e-6 m, so their difference keeps
// about 1e-16 x 1e-6 / 1e-9 = 1e-13 relative; 1e-8 leaves room and still catches a factor sqrt(2) or a
// level off by one (the stiffness changes by more than 1e-3 from one level to the next on these surfaces).
TEST(PlateauHertzStiffness, EqualsTheSecantOfItsOwnLoadWithinALevelStep) {
  for (const std::uint64_t seed : {3u, 11u, 29u}) {
    const Surface s = random_surface(64, seed);
    const SweepCurve sw = sweep(s, SweepLevels::exact(), Topology::for_surface(Connectivity::four, true));
    const LoadAreaCurve paper = plateau_model(sw);
    const Real a0 = s.grid().nominal_area();
    const std::size_t n = paper.load.size();
    for (const std::size_t j : {n / 20, n / 5, n / 2}) {
      const Real low = paper.load[j - 1], high = paper.load[j];
      ASSERT_LT(low, high) << seed << " " << j;
      // The variant carries P_H = P/sqrt(2) at the paper's level (section 8.3).
      const std::vector<Real> loads{(low + 0.25 * (high - low)) / std::numbers::sqrt2,
                                    (low + 0.75 * (high - low)) / std::numbers::sqrt2};
      const LoadAreaCurve hertz = plateau_hertz_curve_at_loads(sw, paper, loads);
      ASSERT_EQ(hertz.spots[0], hertz.spots[1]);
      const Real secant = (loads[1] - loads[0]) / (hertz.separation[0] - hertz.separation[1]);
      const Real stiffness = plateau_hertz_stiffness(hertz.area_fraction[0], hertz.spots[0], a0);
      EXPECT_NEAR(secant / stiffness, 1, 1e-8) << "seed " << seed << ", level " << j;
      // And 1/sqrt(2) x the paper's model's K = 2 sqrt(A_c N / pi)/A0 at that level (its eq. 2), to
      // round-off.
      const Real paper_k =
          2 * std::sqrt(paper.area_fraction[j] * a0 * paper.spots[j] / std::numbers::pi) / a0;
      EXPECT_NEAR(stiffness * std::numbers::sqrt2 / paper_k, 1, 1e-12) << seed << " " << j;
    }
  }
}

// Over a wider step the load curve is piecewise linear with a slope that changes from level to level, so a
// central difference over loads 2 % apart is the mean of the slopes of the steps it spans, weighted by their
// length in z: it must lie between the smallest and the largest K_H of those steps (slack 1e-9 relative for
// round-off, as above). The stiffness at the middle load agrees with it only to the level noise: 1 to 4 %
// measured on this 64^2 surface, printed, not asserted.
TEST(PlateauHertzStiffness, ACentralDifferenceLiesWithinTheStiffnessesItSpans) {
  const Surface s = random_surface(64, 5);
  const SweepCurve sw = sweep(s, SweepLevels::exact(), Topology::for_surface(Connectivity::four, true));
  const LoadAreaCurve paper = plateau_model(sw);
  const Real a0 = s.grid().nominal_area();
  for (const Real load : {1e-3, 1e-2, 3e-2}) {
    const std::vector<Real> loads{load * 0.99, load, load * 1.01};
    const LoadAreaCurve hertz = plateau_hertz_curve_at_loads(sw, paper, loads);
    const Real secant = (loads[2] - loads[0]) / (hertz.separation[0] - hertz.separation[2]);
    // The steps spanned: paper's levels j whose step (P[j-1], P[j]] meets sqrt(2) x [loads[0], loads[2]].
    Real smallest = INFINITY, largest = 0;
    for (std::size_t j = 1; j < paper.load.size(); ++j) {
      if (paper.load[j] < loads[0] * std::numbers::sqrt2 ||
          paper.load[j - 1] > loads[2] * std::numbers::sqrt2)
        continue;
      const Real k = 2 * std::sqrt(paper.area_fraction[j] * a0 * paper.spots[j] / std::numbers::pi) / a0 /
                     std::numbers::sqrt2;
      smallest = std::min(smallest, k);
      largest = std::max(largest, k);
    }
    EXPECT_GE(secant, smallest * (1 - 1e-9)) << load;
    EXPECT_LE(secant, largest * (1 + 1e-9)) << load;
    const Real middle = plateau_hertz_stiffness(hertz.area_fraction[1], hertz.spots[1], a0);
    std::printf("load %g: central difference / K_H at the middle load = %.4f\n", load, secant / middle);
  }
}

TEST(PlateauHertzStiffness, TheSceneMethodGivesIt) {
  const Scene scene = parse_scene("name = \"k\"\ncompare = [\"stiffness\"]\n" + kSmallSurfaceAndMaterial +
                                      "[loads]\nvalues = [1e-3, 1e-2]\n[methods.plateau]\n"
                                      "[methods.plateau_hertz]\n",
                                  "test.toml");
  const SceneReport report = run_scene(scene, {.threads = 1, .observer = nullptr});
  ASSERT_EQ(report.methods.size(), 2u);
  const MethodCurve& hertz = report.methods[1].curve;
  ASSERT_EQ(hertz.stiffness.size(), 2u);
  const Real a0 = 200e-6 * 200e-6, estar = scene.material.estar;
  for (std::size_t k = 0; k < 2; ++k) {
    ASSERT_TRUE(std::isfinite(hertz.stiffness[k])) << k;
    // The method's column is the theory's formula times E*, at the row's area and spots (round-off).
    EXPECT_NEAR(
        hertz.stiffness[k] / (estar * plateau_hertz_stiffness(hertz.area_fraction[k], hertz.spots[k], a0)), 1,
        1e-12);
  }
}

}  // namespace
}  // namespace contactbench
