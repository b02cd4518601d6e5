// The cheap adhesive models (docs/theory.md section 10.4): GW summits each a JKR sphere (Fuller–Tabor,
// theories/fuller_tabor.hpp) or a Maugis–Dugdale sphere (Maugis–GW,
// theories/maugis_greenwood_williamson.hpp), in their limits: one summit is the single sphere, vanishing work
// is GW, Maugis–GW spans DMT and Fuller–Tabor; and as methods of a scene beside the adhesive BEM.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/theories/adhesive_summits.hpp"
#include "contactbench/theories/fuller_tabor.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/jkr_sphere.hpp"
#include "contactbench/theories/maugis_dugdale_sphere.hpp"
#include "contactbench/theories/maugis_greenwood_williamson.hpp"

namespace contactbench {
namespace {

// A soft solid and a clean interface (the scenes of scenes/adhesion): E* = 4 MPa, w = 50 mJ/m^2.
constexpr Real kModulus = 4e6, kWork = 0.05;

// Summits like those of surface A at 256^2 (McCool's from its moments): eta, beta, sigma_s, ys.
GwParameters surface_like_summits() {
  return {.eta = 1.2e11, .beta = 1.5e-6, .sigma_s = 0.45e-6, .ys = 0.2e-6};
}

// σ0 that gives Maugis' parameter λ for summits of radius R.
AdhesionLaw dugdale_with_lambda(Real lambda, Real radius, Real work = kWork) {
  const Real stress = lambda / 2 / std::cbrt(9 * radius / (16 * M_PI * work * kModulus * kModulus));
  return AdhesionLaw::dugdale(work, stress);
}

TEST(JkrSphere, IsMaugisLargeLambdaLimitWithItsPullOffAndEnds) {
  // The closed forms against their defining properties: pull-off −1.5 at ā = (3/2)^(1/3) (dP̄/dā = 0),
  // δ̄ = 0 at the touch radius, dδ̄/dā = 0 at the separation radius: a few ulps of the arithmetic (1e-14).
  const JkrState pull = jkr_at_radius(std::cbrt(1.5));
  EXPECT_NEAR(pull.load, -1.5, 1e-14);
  EXPECT_NEAR(jkr_at_radius(jkr_radius_at_touch()).approach, 0, 1e-14);
  EXPECT_NEAR(jkr_at_radius(jkr_radius_at_separation()).approach_slope, 0, 1e-14);
  EXPECT_NEAR(jkr_at_radius(jkr_radius_at_separation()).approach, -0.9085603, 1e-7);  // 7 figures printed
  // Maugis at λ = 1000 is JKR to O(1/λ) (Johnson & Greenwood 1997): within 0.5 % at ā = 0.5, 1, 2; a wrong
  // factor in either JKR formula (√6, √(8/3)) would be off by tens of percent.
  for (const Real a : {0.5, 1.0, 2.0}) {
    const MaugisDugdaleState md = maugis_dugdale_at_radius(a, 1000);
    const JkrState jkr = jkr_at_radius(a);
    EXPECT_NEAR(jkr.load, md.load, 5e-3 * std::abs(md.load)) << a;
    EXPECT_NEAR(jkr.approach, md.approach, 5e-3 * std::max<Real>(std::abs(md.approach), 0.1)) << a;
  }
}

TEST(MaugisDugdaleSummit, SlopeIsTheDerivativeOfTheApproach) {
  // dδ̄/dā by implicit differentiation against a central difference of Maugis' δ̄ (step 1e-5 ā: truncation
  // ~1e-10, the root of m to 1e-15 adds ~1e-10): agreement to 1e-6 relative to the scale of δ̄'s terms.
  for (const Real lambda : {0.05, 0.3, 1.0, 5.0, 50.0})
    for (const Real a : {0.2, 0.7, 1.5, 4.0}) {
      const Real h = 1e-5 * a;
      const Real fd = (maugis_dugdale_at_radius(a + h, lambda).approach -
                       maugis_dugdale_at_radius(a - h, lambda).approach) /
                      (2 * h);
      EXPECT_NEAR(maugis_dugdale_summit_state(a, lambda).approach_slope, fd, 1e-6 * (2 * a + lambda))
          << "lambda " << lambda << " a " << a;
    }
  // The turn of the branch is where the slope vanishes, and the JKR one at large λ (O(1/λ): 1 % at λ = 200);
  // at λ = 0.1 the branch has none (δ̄ rises from ā -> 0, printed in docs/theory.md 10.4) and starts at 1e-4.
  EXPECT_EQ(maugis_dugdale_radius_at_separation(0.1), 1e-4);
  EXPECT_GT(maugis_dugdale_summit_state(1e-4, 0.1).approach_slope, 0);
  for (const Real lambda : {1.0, 3.0, 10.0}) {
    const Real turn = maugis_dugdale_radius_at_separation(lambda);
    EXPECT_NEAR(maugis_dugdale_summit_state(turn, lambda).approach_slope, 0, 1e-9) << lambda;
  }
  EXPECT_NEAR(maugis_dugdale_radius_at_separation(200), jkr_radius_at_separation(),
              0.01 * jkr_radius_at_separation());
}

// One summit: with a vanishing height spread (sigma_s = 1e-4 S_δ), every summit has the same approach and
// the population is eta times the single sphere. The spread enters at second order, (sigma_s/S_δ)^2 P̄'' ~
// 1e-8, so 1e-6 relative holds; a wrong scale (S_P, S_a, E*) or Jacobian would be off by O(1).
void expect_single_sphere(const AdhesiveSummit& summit, const std::vector<Real>& approaches,
                          const std::function<Real(Real)>& radius_at,
                          const std::function<Real(Real)>& load_at) {
  GwParameters gw = surface_like_summits();
  gw.sigma_s = 1e-4 * summit.scales.approach;
  const AdhesiveSummitPopulation population(gw, summit, kModulus);
  for (const Real approach : approaches) {
    SCOPED_TRACE("approach " + std::to_string(approach));
    // d = ys − δ: t = −δ/sigma_s.
    const AdhesiveSummitsState state = population.at(-approach * summit.scales.approach / gw.sigma_s);
    const Real load = gw.eta * summit.scales.load * load_at(approach) / kModulus;
    EXPECT_NEAR(state.load, load, 1e-6 * std::abs(load));
    const Real a = radius_at(approach);
    const Real area = gw.eta * M_PI * std::pow(a * summit.scales.radius, 2);
    EXPECT_NEAR(state.area_fraction, area, 1e-6 * area + 1e-300);
    EXPECT_NEAR(state.spot_density, a > 0 ? gw.eta : 0, 1e-6 * gw.eta);
  }
}

// JKR's radius on its branch in contact at an approach (bisection on δ̄ = ā² − √(8ā/3) above the turn), or 0
// below `first`, the approach where the branch's summits begin.
Real jkr_radius(Real approach, Real first) {
  if (approach < first) return 0;
  Real lo = jkr_radius_at_separation(), hi = 100;
  for (int k = 0; k < 200; ++k)
    (jkr_at_radius(0.5 * (lo + hi)).approach < approach ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

TEST(FullerTabor, OneSummitIsTheJkrSphere) {
  const GwParameters gw = surface_like_summits();
  for (const AdhesiveBranch branch : {AdhesiveBranch::approach, AdhesiveBranch::retract}) {
    SCOPED_TRACE(std::string(adhesive_branch_name(branch)));
    const AdhesiveSummit summit = fuller_tabor_summit(gw.beta, kModulus, kWork, branch);
    const Real first = jkr_at_radius(summit.first_radius).approach;  // 0, or −0.9086 on retract
    auto radius = [first](Real approach) { return jkr_radius(approach, first); };
    auto load = [first](Real approach) {
      return approach < first ? 0 : jkr_at_radius(jkr_radius(approach, first)).load;
    };
    // On the approach branch a summit pulled to δ̄ = −0.5 is out of contact and JKR pulls nothing there;
    // on the retract branch it is still in contact (it jumps off at −0.9086).
    expect_single_sphere(summit, {-0.5, 0.01, 0.5, 3.0}, radius, load);
  }
}

// Maugis' radius on its branch in contact at an approach, 0 below the branch's first approach.
Real maugis_radius(Real approach, Real first, Real lambda) {
  if (approach < first) return 0;
  Real lo = maugis_dugdale_radius_at_separation(lambda), hi = 100;
  for (int k = 0; k < 200; ++k)
    (maugis_dugdale_at_radius(0.5 * (lo + hi), lambda).approach < approach ? lo : hi) = 0.5 * (lo + hi);
  return 0.5 * (lo + hi);
}

TEST(MaugisGw, OneSummitIsTheMaugisDugdaleSphereAndPullsOutOfContactAsDerjaguin) {
  const GwParameters gw = surface_like_summits();
  for (const Real lambda : {0.3, 1.0, 3.0})
    for (const AdhesiveBranch branch : {AdhesiveBranch::approach, AdhesiveBranch::retract}) {
      SCOPED_TRACE("lambda " + std::to_string(lambda) + " " + std::string(adhesive_branch_name(branch)));
      const AdhesionLaw law = dugdale_with_lambda(lambda, gw.beta);
      const AdhesiveSummit summit = maugis_dugdale_summit(gw.beta, kModulus, law, branch);
      const Real first = maugis_dugdale_at_radius(summit.first_radius, lambda).approach;
      // Out of contact within reach δ̄c = δc/S_δ = 2/(πλ): P̄ = −2 (1 − h0/δc), the rigid sphere's pull.
      const Real reach = law.reach() / summit.scales.approach;
      EXPECT_NEAR(reach, 2 / (M_PI * lambda), 1e-12 * reach);
      auto radius = [&](Real approach) { return maugis_radius(approach, first, lambda); };
      auto load = [&](Real approach) {
        if (approach >= first) return maugis_dugdale_at_radius(radius(approach), lambda).load;
        return approach > -reach && approach < 0 ? -2 * (1 + approach / reach) : 0.0;
      };
      expect_single_sphere(summit, {0.5 * (std::min<Real>(first, 0) - reach), first + 0.2, 0.5, 3.0}, radius,
                           load);
    }
}

// Vanishing work: Fuller–Tabor and Maugis–GW (at a fixed λ = 1) are GW. At the same separation the adhesive
// share of the load scales as w and the excess area as w^(1/2) (JKR: a² = Rδ + R √(2π w a/E*); measured on
// these summits 1.06e-4 at w = 1e-9 J/m^2, 3.3e-6 at 1e-12, 1.1e-7 at 1e-15): at w = 1e-12, A/A0 at the same
// load within 1e-5 relative and the separation within 1e-5 sigma_s. At w = 0.05 the area must grow by more
// than 1 %.
TEST(AdhesiveSummits, VanishingWorkIsGreenwoodWilliamson) {
  const GwParameters gw = surface_like_summits();
  for (const Real load : {1e-3, 1e-2}) {
    const Real t = gw_solve_separation(gw, load);
    const Real area = gw_area_fraction(gw, t);
    for (const AdhesiveSummit& summit :
         {fuller_tabor_summit(gw.beta, kModulus, 1e-12, AdhesiveBranch::approach),
          maugis_dugdale_summit(gw.beta, kModulus, dugdale_with_lambda(1, gw.beta, 1e-12),
                                AdhesiveBranch::approach)}) {
      const AdhesiveSummitPopulation population(gw, summit, kModulus);
      const Real t_sticky = population.solve(std::vector<Real>{load}, AdhesiveBranch::approach, "test")[0];
      EXPECT_NEAR(population.at(t_sticky).area_fraction, area, 1e-5 * area) << load;
      EXPECT_NEAR(t_sticky, t, 1e-5) << load;
    }
    const AdhesiveSummitPopulation sticky(
        gw, fuller_tabor_summit(gw.beta, kModulus, kWork, AdhesiveBranch::approach), kModulus);
    const Real t_sticky = sticky.solve(std::vector<Real>{load}, AdhesiveBranch::approach, "test")[0];
    EXPECT_GT(sticky.at(t_sticky).area_fraction, 1.01 * area) << "w = 50 mJ/m^2 must grow the area";
  }
}

}  // namespace
}  // namespace contactbench
