// The adhesive BEM (bem/adhesive_solver.hpp) in the analytic limits that do not depend on the law's shape
// (docs/theory.md section 10.2 and 10.8): the exponential law on a sphere at small Tabor parameter (DMT:
// the pull-off tends to 2πRw, the rigid sphere's Derjaguin force), its move toward JKR (1.5πRw) as the
// parameter grows, and Kendall's rigid flat punch.
//
// The sphere: R = 1 mm, E* = 1 MPa, w = 50 mJ/m^2 (the calibration of issue 34), non-periodic. The
// exponential law a(g) = (w/ρ) exp(-g/ρ) takes ρ = w/σ0 with σ0 the peak stress of Maugis' λ (AdhesionLaw's
// maugis_parameter uses the peak stress). Pull-offs are the most tensile load of a retract scan.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "contact_shapes.hpp"
#include "contactbench/bem/adhesive_solver.hpp"
#include "contactbench/theories/maugis_dugdale_sphere.hpp"

namespace contactbench {
namespace {

constexpr Real kModulus = 1e6, kWork = 0.05, kRadius = 1e-3;

// The peak stress σ0 that gives Maugis' λ for the sphere above.
Real peak_stress(Real lambda) {
  return lambda / 2 / std::cbrt(9 * kRadius / (16 * M_PI * kWork * kModulus * kModulus));
}

struct Scan {
  Real least_load = 0;      // P/(πRw), the pull-off of the scan
  Real rigid_touching = 0;  // the attraction of the undeformed sphere at touching, P/(πRw), same grid
};

// Approach 2.5 MD units into contact, then retract through the approaches `from` down to `to` (MD units,
// δ̄ = δ/(π²w²R/K²)^(1/3)) in `steps` equal steps, keeping the most tensile load.
Scan retract_scan(const AdhesionLaw& law, Index n, Real side, Real from, Real to, int steps) {
  const Real dx = side / n;
  const Surface s = sphere(n, dx, kRadius);
  AdhesiveSolverOptions options;
  options.contact.tolerance = 1e-8;
  AdhesiveBemSolver solver(s, kModulus, law, options, 2);
  const MaugisDugdaleScales scale = maugis_dugdale_scales(kRadius, kModulus, kWork);
  const HeightMap& h = solver.surface().heights();
  const Real top = h.maxCoeff();
  Scan scan;
  for (Index iy = 0; iy < n; ++iy)
    for (Index ix = 0; ix < n; ++ix)
      scan.rigid_touching -= law.attraction(top - h(iy, ix)) * dx * dx / scale.load;
  solver.solve_for_separation(top - 2.5 * scale.approach);
  for (int k = 0; k <= steps; ++k) {
    const Real approach = from + (to - from) * k / steps;
    const AdhesiveSolution& r = solver.solve_for_separation(top - approach * scale.approach);
    EXPECT_TRUE(r.converged) << "approach " << approach;
    scan.least_load = std::min(scan.least_load, r.mean_pressure * s.grid().nominal_area() / scale.load);
  }
  return scan;
}

// DMT: as λ -> 0 the sphere barely deforms, contact ends with the apex just touching, and the pull-off is the
// rigid sphere's attraction there, 2πRw ∫ a dg / w = 2πRw (Derjaguin). λ = 0.02: ρ = 76 μm, the window of
// 2 mm holds the attraction out to gaps of 6.5 ρ (e^-6.5 = 0.15 % of the force left out) on 31 μm pixels,
// against the attraction's radial scale √(2Rρ) = 390 μm. Measured: pull-off -1.9946, the same grid's rigid
// sphere -1.9988, MD's Dugdale sphere at λ = 0.02 -1.9952. Tolerances: 0.5 % to 2πRw (window and MD's own
// distance from DMT at this λ, 0.24 %); 0.3 % to the same grid's rigid sphere, whose discretisation and
// window the pull-off shares (the elastic correction at λ = 0.02 is 0.2 %). Then λ = 0.1 (ρ = 15 μm, 900 μm
// on 64^2): measured -1.9643, 1.8 % from DMT, MD -1.9506; the move away from DMT grows with λ.
TEST(ExponentialSphere, DmtLimitAtSmallTabor) {
  const Real lambda = 0.02;
  const AdhesionLaw law = AdhesionLaw::exponential(kWork, kWork / peak_stress(lambda));
  const Scan scan = retract_scan(law, 64, 2e-3, 0.0, -0.5, 10);
  EXPECT_NEAR(scan.rigid_touching, -2.0, 0.005 * 2.0);
  EXPECT_NEAR(scan.least_load, -2.0, 0.005 * 2.0);
  EXPECT_NEAR(scan.least_load, scan.rigid_touching, 0.003 * 2.0);
  EXPECT_GT(scan.least_load, scan.rigid_touching);  // the elastic sphere pulls less than the rigid one
  const Scan wider =
      retract_scan(AdhesionLaw::exponential(kWork, kWork / peak_stress(0.1)), 64, 900e-6, -0.2, -0.5, 6);
  EXPECT_GT(wider.least_load, scan.least_load + 0.01);  // toward JKR, measured by 0.030
  // Against MD's Dugdale sphere of equal work and peak stress (a different law: ContactMechanics measured the
  // exponential law 2-3 % more adhesive near λ = 1): measured +0.7 % at λ = 0.1; 1.5 % allowed.
  const Real md = maugis_dugdale_pull_off(0.1).load;
  EXPECT_NEAR(wider.least_load, md, 0.015 * std::abs(md));
}

// JKR side: as λ grows the pull-off falls toward 1.5πRw. A resolved λ large enough to be within 1 % of JKR is
// out of a test's reach (the zone is about 2 % of the radius at λ = 3); measured for the exponential law
// (300 μm window, retract steps of 0.1 MD approach units): λ = 1 -1.681 (64² over 320 μm, zone 6 pixels),
// λ = 2 -1.586 (128², zone 4), λ = 3 -1.554 (128², zone 1.8) and -1.547 (256², zone 4), against MD's
// -1.601, -1.535, -1.517: the exponential law of equal work and peak stress is 2-5 % more adhesive than the
// Dugdale one, and both tend to -1.5. Tested at λ = 2, 128²: between JKR and DMT, below λ = 0.1's value, and
// within 5 % of MD (measured +3.3 %: the law's 2-3 % that ContactMechanics measured at 256², and about
// 0.5 % of grid, the change from 128² to 256² at λ = 3).
TEST(ExponentialSphere, TendsTowardJkrAsTaborGrows) {
  const Real lambda = 2;
  const AdhesionLaw law = AdhesionLaw::exponential(kWork, kWork / peak_stress(lambda));
  const Scan scan = retract_scan(law, 128, 300e-6, -0.4, -0.6, 2);
  const Real md = maugis_dugdale_pull_off(lambda).load;
  EXPECT_LT(scan.least_load, -1.5);
  EXPECT_GT(scan.least_load, -1.9);  // well away from DMT (λ = 0.1 gives -1.96)
  EXPECT_NEAR(scan.least_load, md, 0.05 * std::abs(md));
}

// Kendall's rigid flat punch (K. Kendall, J. Phys. D 4, 1186, 1971): a face of radius a stuck to the
// half-space comes off at F = √(8π a³ E* w), the Griffith limit of a crack at the face's rim. With a Dugdale
// law the rim is a cohesive zone of length ℓ = (π/8) E* w/σ0² (Dugdale–Barenblatt, plane strain), and
// Kendall's answer is the limit ℓ/a -> 0 (docs/theory.md section 10.8): the zone's σ0 πa² alone would be
// (π/8) √(a/ℓ) F, so Kendall needs a/ℓ ≫ 1, and the zone must still span pixels. The pull-off of a punch of
// a pixels with a zone of ℓ pixels, in units of Kendall's force: the face (the nodes within the radius) at
// height 0, the rest 100 μm lower (out of the law's reach), 1 μm pixels, non-periodic (the window's margin
// does not matter: measured identical with 8 and 16 pixels). Pressed to 0.05 δK above touching
// (δK = F/(2E* a), Kendall's approach at pull-off), then retracted in steps of 4 % of δK until the face lets
// go; the load rises linearly to the last state in contact, so the last steps are redone from the last
// state in contact in steps of 0.4 % of δK (the error of the pull-off is below 0.4 % of F).
Real punch_pull_off_over_kendall(Index radius_pixels, Real zone_pixels, AdhesiveMethod method) {
  const Real dx = 1e-6;
  const Index n = 2 * radius_pixels + 4;
  const Grid grid{.nx = n, .ny = n, .lx = n * dx, .ly = n * dx, .periodic = false};
  HeightMap h(n, n);
  Index face = 0;
  for (Index iy = 0; iy < n; ++iy)
    for (Index ix = 0; ix < n; ++ix) {
      const Real x = ix - n / 2 + 0.5, y = iy - n / 2 + 0.5;
      const bool on_face = x * x + y * y < static_cast<Real>(radius_pixels * radius_pixels);
      h(iy, ix) = on_face ? 0 : -100e-6;
      face += on_face;
    }
  const Surface s(grid, h);
  const Real sigma0 = std::sqrt(M_PI * kModulus * kWork / (8 * zone_pixels * dx));
  AdhesiveSolverOptions options;
  options.contact.tolerance = 1e-8;
  options.method = method;
  AdhesiveBemSolver solver(s, kModulus, AdhesionLaw::dugdale(kWork, sigma0), options, 2);
  const Real top = solver.surface().heights().maxCoeff();
  const Real a = std::sqrt(static_cast<Real>(face) / M_PI) * dx;  // the face's area as a disc
  const Real kendall = std::sqrt(8 * M_PI * a * a * a * kModulus * kWork);
  const Real approach_scale = kendall / (2 * kModulus * a);
  Real least = 0;
  // Retract from `from` in steps of `step` (units of δK) until the face lets go; returns the last approach in
  // contact.
  auto retract = [&](Real from, Real step) {
    Real last_in_contact = from;
    for (Real approach = from; approach > -3; approach -= step) {
      const AdhesiveSolution& r = solver.solve_for_separation(top - approach * approach_scale);
      EXPECT_TRUE(r.converged) << "approach " << approach;
      if (r.contact_points == 0) break;
      least = std::min(least, r.mean_pressure * grid.nominal_area());
      last_in_contact = approach;
    }
    return last_in_contact;
  };
  const Real last = retract(0.05, 0.04);
  solver.forget();
  solver.solve_for_separation(top - 0.05 * approach_scale);
  for (Real approach = 0.05; approach > last; approach -= 0.04)  // the same states as before
    solver.solve_for_separation(top - approach * approach_scale);
  retract(last, 0.004);
  return -least / kendall;
}

// Measured (1 μm pixels; F/F_Kendall): a/ℓ = 4: 0.783 (a = 8, ℓ = 2 pixels) and 0.776 (a = 16, ℓ = 4);
// a/ℓ = 8: 0.900 (a = 16, ℓ = 2) and 0.892 (a = 32, ℓ = 4); a/ℓ = 16: 0.947 (a = 32, ℓ = 2; not a test: 20 s
// of CPU). So the
// ratio is set by a/ℓ, not by the pixel, once the zone spans 2 pixels, and 1 - F/F_K falls as ℓ/a: the
// cohesive zone moves the crack's effective tip by a fraction of ℓ, a correction of first order in ℓ/a.
// Kendall's limit itself (1 % needs a/ℓ of several hundred, a of about 1000 pixels) is out of a test's
// reach; its first-order extrapolation from a/ℓ = 4 and 8 is tested instead.
// Both methods of the Dugdale law (AdhesiveSolverOptions::method) are held to the same checks.
class KendallPunch : public ::testing::TestWithParam<AdhesiveMethod> {};

TEST_P(KendallPunch, PullOffTendsToKendallAsTheZoneShrinks) {
  const Real coarse = punch_pull_off_over_kendall(8, 2, GetParam());
  const Real fine = punch_pull_off_over_kendall(16, 2, GetParam());
  const Real same_ratio = punch_pull_off_over_kendall(16, 4, GetParam());
  // The pixel does not matter at a fixed a/ℓ: measured 0.8 % apart; 2 % allowed (a zone of 2 pixels).
  EXPECT_NEAR(same_ratio, coarse, 0.02);
  // Both below Kendall (the zone's finite stress gives way first) and closer at the larger a/ℓ.
  EXPECT_LT(coarse, fine);
  EXPECT_LT(fine, 1.0);
  // First order in ℓ/a: the shortfall halves when a/ℓ doubles (measured 2.16 from 4 to 8, 1.89 from 8 to 16;
  // 1.6 to 2.7 admits an order between 0.7 and 1.4).
  const Real halving = (1 - coarse) / (1 - fine);
  EXPECT_GT(halving, 1.6);
  EXPECT_LT(halving, 2.7);
  // Extrapolated to ℓ/a -> 0 at first order: Kendall's force within 3 % (measured 1.016; from a/ℓ = 8 and 16
  // it is 0.994, so the extrapolation is good to about 2 % from the pair tested).
  EXPECT_NEAR(2 * fine - coarse, 1.0, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Methods, KendallPunch,
                         ::testing::Values(AdhesiveMethod::fixed_point, AdhesiveMethod::constrained_cg),
                         [](const auto& info) { return std::string(adhesive_method_name(info.param)); });

}  // namespace
}  // namespace contactbench
