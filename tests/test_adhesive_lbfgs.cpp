// The exponential law's whole-surface minimisation (adhesive_solver = "projected_lbfgs",
// bem/adhesive_lbfgs.hpp, docs/theory.md section 10.11) against the non-adhesive solve (w -> 0), the fixed
// point of section 10.3 on the same grid, Maugis' Dugdale sphere of equal work and peak stress, and on a
// rough surface; and its refusals.
//
// The sphere: R = 1 mm, E* = 1 MPa, w = 50 mJ/m^2 (the calibration of issue 34) on a periodic window (the
// method's problem) that holds the attraction: gaps at the window's edge are hundreds of ranges.
#include <gtest/gtest.h>

#include <cmath>
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

Surface periodic_sphere(Index n, Real side) {
  return sphere(n, side / n, kRadius).with_periodic(true);
}

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
    ASSERT_TRUE(x.converged);
    ASSERT_TRUE(y.converged);
    // The same equilibrium: measured the same contact points, mean gaps within 6e-7 and load potentials
    // within 1e-9 relative. Both stop at a force imbalance of 1e-6 of the peak stress, which moves a gap by
    // about 1e-6 ρ; allowed: the same contact set, and 1e-5 of the mean gap and of the potential.
    EXPECT_EQ(y.contact_points, x.contact_points);
    EXPECT_NEAR(y.mean_gap, x.mean_gap, 1e-5 * x.mean_gap);
    EXPECT_NEAR(load_potential(whole), load_potential(fixed), 1e-5 * std::abs(load_potential(fixed)));
    EXPECT_NEAR(y.mean_pressure, load * scale.load / area, 1e-9 * scale.load / area);
    EXPECT_GT(y.zone_pixels, 5);  // resolved (measured 9-10 pixels)
    // Against Maugis' Dugdale sphere: measured -1.5 %, -1.3 % and +0.1 % at P/(πRw) = 1, 0, -1, the law's own
    // 0.5-0.8 % below (ContactMechanics, issue 34) and about 1 % of grid (the Dugdale law's 1.3 % at this
    // resolution, tests/test_adhesive_bem.cpp); the 3 % allowed.
    const Real radius = std::sqrt(static_cast<Real>(y.contact_points) * dx * dx / M_PI) / scale.radius;
    const Real md = maugis_dugdale_radius_at_load(load, lambda);
    EXPECT_NEAR(radius, md, 0.03 * md);
  }
  // The pull-off under load control: tensile loads in steps of 0.02 πRw, each warm from the last, down to the
  // first that no state in contact holds; the pull-off is between the last held load and that one.
  Real held = -1;
  for (Real load = -1.6; load > -2.2; load -= 0.02) {
    const AdhesiveSolution& y = whole.solve(load * scale.load / area);
    if (!y.converged || y.contact_points == 0) break;
    held = load;
  }
  // Measured: held at -1.70, not at -1.72: 6.2 % more adhesive than MD's -1.6007 (the fixed point's scan on
  // 64^2, non-periodic, tests/test_adhesive_limits.cpp: -1.681, 5.0 %). The exponential law of equal work and
  // peak stress is the more adhesive law (2-5 % in docs/theory.md 10.8, ContactMechanics 2-3 % at 256^2);
  // this grid and window give a little more, reported as measured. Allowed: more adhesive than MD, and within
  // 8 %.
  const Real pull_off = maugis_dugdale_pull_off(lambda).load;
  EXPECT_LT(held, pull_off);
  EXPECT_NEAR(held, pull_off, 0.08 * std::abs(pull_off));
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
  ASSERT_TRUE(x.converged);
  ASSERT_TRUE(y.converged);
  // Measured: the same 4312 contact and 12037 attractive points, the mean gaps within 2e-6 and the load
  // potentials to 9 digits (the zone 3.5 pixels). Allowed as for the sphere: the same sets, 1e-5 of the mean
  // gap and of the potential (a different equilibrium would move the counts by whole pixels).
  EXPECT_GT(x.zone_pixels, 2);
  EXPECT_EQ(y.contact_points, x.contact_points);
  EXPECT_EQ(y.attractive_points, x.attractive_points);
  EXPECT_NEAR(y.mean_gap, x.mean_gap, 1e-5 * x.mean_gap);
  EXPECT_NEAR(load_potential(whole), load_potential(fixed), 1e-5 * std::abs(load_potential(fixed)));
}

// The element-wise passes run on the convolution's team (256^2 is the smallest grid that has two threads,
// core/types.hpp kMinPointsForThreads), their sums over fixed blocks combined in block order. One thread and
// two solve the same problem (the rough surface above on 256^2) to the same state: a race or a block left out
// would move the contact set or the traction by far more. Measured: the same steps, evaluations, contact
// and attractive points, the mean gap within 1e-9, tractions within 9e-4 Pa (1.8e-8 of the 50 kPa peak: the
// one- and two-thread FFT plans round differently, and the iteration carries that). Allowed: equal counts,
// 1e-9 of the mean gap, and the traction within 1e-6 of the peak, the force imbalance both solves stop at
// (100 x the tolerance 1e-8).
TEST(ProjectedLbfgs, OneThreadAndTwoReachTheSameState) {
  const Grid grid{.nx = 256, .ny = 256, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  const Surface s =
      generate_surface(grid, {.sigma = 0.5e-6, .hurst = 0.5, .qr = 3.14e4, .qs = std::nullopt}, 1);
  const Real modulus = 3.948e6;
  const AdhesionLaw law = AdhesionLaw::exponential(kWork, 1e-6);
  AdhesiveBemSolver one(s, modulus, law, options(AdhesiveMethod::projected_lbfgs, 1e-8), 1);
  AdhesiveBemSolver two(s, modulus, law, options(AdhesiveMethod::projected_lbfgs, 1e-8), 2);
  const AdhesiveSolution& x = one.solve(1e-3 * modulus);
  const AdhesiveSolution& y = two.solve(1e-3 * modulus);
  ASSERT_TRUE(x.converged);
  ASSERT_TRUE(y.converged);
  EXPECT_EQ(y.cg_iterations, x.cg_iterations);
  EXPECT_EQ(y.iterations, x.iterations);
  EXPECT_EQ(y.contact_points, x.contact_points);
  EXPECT_EQ(y.attractive_points, x.attractive_points);
  EXPECT_NEAR(y.mean_gap, x.mean_gap, 1e-9 * x.mean_gap);
  EXPECT_LE((y.traction - x.traction).abs().maxCoeff(), 1e-6 * law.peak_stress())
      << "largest difference " << (y.traction - x.traction).abs().maxCoeff() << " Pa";
}

}  // namespace
}  // namespace contactbench
