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

}  // namespace
}  // namespace contactbench
