// The exponential law's whole-surface minimisation (adhesive_solver = "projected_lbfgs", bem/adhesive_lbfgs.hpp,
// docs/theory.md section 10.11) against the non-adhesive solve (w -> 0), the fixed point of section 10.3 on
// the same grid, Maugis' Dugdale sphere of equal work and peak stress, and on a rough surface; and its
// refusals.
//
// The sphere: R = 1 mm, E* = 1 MPa, w = 50 mJ/m^2 (the calibration of issue 34) on a periodic window (the
// method's problem) that holds the attraction: gaps at the window's edge are hundreds of ranges.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "contact_shapes.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/theories/maugis_dugdale_sphere.hpp"

namespace contactbench {
namespace {

constexpr Real kModulus = 1e6, kWork = 0.05, kRadius = 1e-3;

// The peak stress that gives Maugis' λ for the sphere above (core/adhesion_law.hpp's definition).
Real peak_stress(Real lambda) {
  return lambda / 2 / std::cbrt(9 * kRadius / (16 * M_PI * kWork * kModulus * kModulus));
}

AdhesiveSolverOptions options(AdhesiveMethod method, Real tolerance) {
  AdhesiveSolverOptions o;
  o.contact.tolerance = tolerance;
  o.method = method;
  return o;
}

Surface periodic_sphere(Index n, Real side) { return sphere(n, side / n, kRadius).with_periodic(true); }

TEST(ProjectedLbfgs, RefusesWhatItCannotSolve) {
  auto message = [](const Surface& s, const AdhesionLaw& law) -> std::string {
    try {
      AdhesiveBemSolver(s, kModulus, law, options(AdhesiveMethod::projected_lbfgs, 1e-6), 1);
    } catch (const Error& e) {
      return e.what();
    }
    return "accepted";
  };
  const std::string dugdale = message(periodic_sphere(16, 1e-4), AdhesionLaw::dugdale(kWork, 1e4));
  EXPECT_NE(dugdale.find("projected_lbfgs"), std::string::npos) << dugdale;
  EXPECT_NE(dugdale.find("dugdale"), std::string::npos) << dugdale;
  const std::string edges = message(sphere(16, 1e-6, kRadius), AdhesionLaw::exponential(kWork, 1e-6));
  EXPECT_NE(edges.find("periodic"), std::string::npos) << edges;
  EXPECT_EQ(message(periodic_sphere(16, 1e-4), AdhesionLaw::exponential(kWork, 1e-6)), "accepted");
}

// (1) w -> 0: the non-adhesive answer. w = 1e-12 J/m^2 over ρ = 1e-9 m (peak 1e-3 Pa, on contact pressures of
// order 1e4 Pa): the pull changes the traction by at most 1e-3 Pa, 1e-7 of the peak pressure, far below the
// tolerance; the solve stops at a force imbalance of 100 x 1e-10 of the largest pressure. So the same contact
// points, and the traction equal to BemSolver's pressure within 1e-6 of its peak (a pull left on at the
// calibration's peak stress would differ by far more), under load and separation control.
TEST(ProjectedLbfgs, VanishingWorkGivesTheNonAdhesiveAnswer) {
  const Surface s = periodic_sphere(64, 320e-6);
  AdhesiveBemSolver adhesive(s, kModulus, AdhesionLaw::exponential(1e-12, 1e-9),
                             options(AdhesiveMethod::projected_lbfgs, 1e-10), 1);
  BemSolver elastic(s, kModulus, options(AdhesiveMethod::fixed_point, 1e-10).contact, 1);
  const Real load = 1e-3 * kModulus / 64;  // about 20 % of the window's width in contact
  const AdhesiveSolution& a = adhesive.solve(load);
  const ContactSolution& e = elastic.solve(load);
  std::printf("w->0 load: contact %ld vs %ld, traction diff %g of %g, evaluations %ld\n",
              static_cast<long>(a.contact_points), static_cast<long>(e.contact_points),
              (a.traction - e.pressure).cwiseAbs().maxCoeff(), e.pressure.maxCoeff(),
              static_cast<long>(a.iterations));
  ASSERT_TRUE(a.converged);
  EXPECT_EQ(a.contact_points, e.contact_points);
  EXPECT_LE((a.traction - e.pressure).cwiseAbs().maxCoeff(), 1e-6 * e.pressure.maxCoeff());
  EXPECT_NEAR(a.mean_pressure, load, 1e-12 * load);
  const Real d = e.gap.mean();  // periodic: the separation is the mean gap
  const AdhesiveSolution& b = adhesive.solve_for_separation(d);
  ASSERT_TRUE(b.converged);
  EXPECT_EQ(b.contact_points, e.contact_points);
  EXPECT_NEAR(b.mean_pressure, load, 1e-6 * load);
  EXPECT_NEAR(b.mean_gap, d, 1e-12 * d);
}

// The potential that load control makes stationary, U + (P/A0) d (docs/theory.md 10.7) [J/m^2].
Real load_potential(const AdhesiveBemSolver& solver) {
  return solver.energy() + solver.solution().mean_pressure * solver.solution().separation;
}

// (2) The λ = 1 sphere (ρ = 1.53 μm) on 128^2 over 320 μm (2.5 μm pixels), loads P/(πRw) = 1, 0, -1 down the
// stable branch, each solve warm from the last: the fixed point and the minimisation on the same grid, both
// at the tolerance 1e-8, and both against Maugis' Dugdale sphere of equal work and peak stress.
TEST(ProjectedLbfgs, SphereMatchesTheFixedPointAndMaugis) {
  const Real lambda = 1;
  const AdhesionLaw law = AdhesionLaw::exponential(kWork, kWork / peak_stress(lambda));
  const Index n = 128;
  const Real side = 320e-6, dx = side / n;
  const Surface s = periodic_sphere(n, side);
  AdhesiveBemSolver fixed(s, kModulus, law, options(AdhesiveMethod::fixed_point, 1e-8), 2);
  AdhesiveBemSolver whole(s, kModulus, law, options(AdhesiveMethod::projected_lbfgs, 1e-8), 2);
  const MaugisDugdaleScales scale = maugis_dugdale_scales(kRadius, kModulus, kWork);
  const Real area = s.grid().nominal_area();
  for (const Real load : {1.0, 0.0, -1.0}) {
    SCOPED_TRACE("load " + std::to_string(load));
    const AdhesiveSolution& x = fixed.solve(load * scale.load / area);
    const AdhesiveSolution& y = whole.solve(load * scale.load / area);
    const Real radius_x = std::sqrt(static_cast<Real>(x.contact_points) * dx * dx / M_PI) / scale.radius;
    const Real radius_y = std::sqrt(static_cast<Real>(y.contact_points) * dx * dx / M_PI) / scale.radius;
    const Real md = maugis_dugdale_radius_at_load(load, lambda);
    std::printf(
        "sphere load %g: fixed %ld pts gap %.9g pull %.9g it %ld (%ld) | whole %ld pts gap %.9g pull %.9g it %ld "
        "steps %ld | radius %g %g md %g | U %.9g %.9g zone %g res %g %g\n",
        load, static_cast<long>(x.contact_points), x.mean_gap, x.adhesive_pressure, static_cast<long>(x.iterations),
        static_cast<long>(x.outer_iterations), static_cast<long>(y.contact_points), y.mean_gap,
        y.adhesive_pressure, static_cast<long>(y.iterations), static_cast<long>(y.cg_iterations), radius_x,
        radius_y, md, load_potential(fixed), load_potential(whole), y.zone_pixels, x.attraction_change,
        y.attraction_change);
    ASSERT_TRUE(x.converged);
    ASSERT_TRUE(y.converged);
  }
}

// (3) A rough surface at a resolved zone: the surface of scenes/adhesion/surface_A_soft_tabor_0_1.toml
// (contactbench generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 256 --seed 1, here on
// 128^2), E* = 3.948 MPa, w = 50 mJ/m^2, ρ = 1 μm (peak 50 kPa, the Dugdale case of test_adhesive_bem.cpp
// with equal work and peak stress), cold load P/(E* A0) = 1e-3.
TEST(ProjectedLbfgs, RoughSurfaceWhereTheZoneIsResolved) {
  const Grid grid{.nx = 128, .ny = 128, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  const Surface s =
      generate_surface(grid, {.sigma = 0.5e-6, .hurst = 0.5, .qr = 3.14e4, .qs = std::nullopt}, 1);
  const Real modulus = 3.948e6;
  const AdhesionLaw law = AdhesionLaw::exponential(kWork, 1e-6);
  AdhesiveBemSolver fixed(s, modulus, law, options(AdhesiveMethod::fixed_point, 1e-8), 2);
  AdhesiveBemSolver whole(s, modulus, law, options(AdhesiveMethod::projected_lbfgs, 1e-8), 2);
  const AdhesiveSolution& x = fixed.solve(1e-3 * modulus);
  const AdhesiveSolution& y = whole.solve(1e-3 * modulus);
  std::printf(
      "rough: fixed %ld pts %ld attr gap %.9g it %ld (%ld) %.3fs | whole %ld pts %ld attr gap %.9g it %ld steps "
      "%ld %.3fs | U %.9g %.9g zone %g %g\n",
      static_cast<long>(x.contact_points), static_cast<long>(x.attractive_points), x.mean_gap,
      static_cast<long>(x.iterations), static_cast<long>(x.outer_iterations), x.seconds,
      static_cast<long>(y.contact_points), static_cast<long>(y.attractive_points), y.mean_gap,
      static_cast<long>(y.iterations), static_cast<long>(y.cg_iterations), y.seconds, load_potential(fixed),
      load_potential(whole), x.zone_pixels, y.zone_pixels);
  ASSERT_TRUE(x.converged);
  ASSERT_TRUE(y.converged);
}

}  // namespace
}  // namespace contactbench
