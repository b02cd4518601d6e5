// The exact solutions (tests/reference_solutions.hpp) checked on their own before they judge the solvers:
// each against an independent property (equilibrium: the pressure integrates to the load; consistency of its
// formulas with each other; the half-space's exact response to one wave, u(q) = 2 p(q)/(E* |q|)).
#include "reference_solutions.hpp"
#include "test_constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <utility>

namespace contactbench::reference {
namespace {

// Composite Simpson's rule on [a, b] with n (even) intervals: error (b - a) h^4 f''''/180.
Real simpson(const std::function<Real(Real)>& f, Real a, Real b, int n) {
  const Real h = (b - a) / n;
  Real sum = f(a) + f(b);
  for (int i = 1; i < n; ++i)
    sum += (i % 2 ? 4 : 2) * f(a + i * h);
  return sum * h / 3;
}

// Smooth integrands (after the substitutions below) on 2000 Simpson intervals: round-off, 1e-12.
constexpr Real kQuadrature = 1e-12;

TEST(ReferenceHertz, PressureIntegratesToTheLoad) {
  const HertzSphere hertz{.radius = 1e-3, .modulus = testing::kPaperModulus};
  for (const Real load : {1e-3, 0.1, 10.0}) {
    const Real a = hertz.contact_radius(load);
    // r = a sin(t): the square root becomes cos(t), smooth on [0, pi/2].
    const Real total = simpson(
        [&](Real t) {
          return hertz.pressure(a * std::sin(t), load) * 2 * pi * a * std::sin(t) * a * std::cos(t);
        },
        0, pi / 2, 2000);
    EXPECT_NEAR(total, load, kQuadrature * load) << load;
  }
}

TEST(ReferenceHertz, ItsFormulasAgreeWithEachOther) {
  const HertzSphere hertz{.radius = 2e-3, .modulus = testing::kPaperModulus};
  const Real load = 0.5;
  // Round-off of a few powers and roots: 1e-14.
  EXPECT_NEAR(hertz.load_of_contact_radius(hertz.contact_radius(load)), load, 1e-14 * load);
  EXPECT_NEAR(hertz.load_of_approach(hertz.approach(load)), load, 1e-14 * load);
  // p0 = (6 P E*^2/(pi^3 R^2))^(1/3) (Johnson 1985, eq. 4.23), another arrangement of the same law.
  EXPECT_NEAR(hertz.peak_pressure(load),
              std::cbrt(6 * load * testing::kPaperModulus * testing::kPaperModulus /
                        (pi * pi * pi * hertz.radius * hertz.radius)),
              1e-14 * hertz.peak_pressure(load));
  EXPECT_EQ(hertz.pressure(1.01 * hertz.contact_radius(load), load), 0);
}

TEST(ReferenceFlatPunch, PressureIntegratesToTheLoadAndHertzStiffnessIsThePunchs) {
  const FlatPunch punch{.radius = 20e-6, .modulus = testing::kPaperModulus};
  const Real load = 0.3, a = punch.radius;
  // r = a sin(t): the inverse square root singularity at the edge cancels against dr = a cos(t) dt. The
  // midpoint rule never evaluates the edge itself (where a^2 - r^2 cancels): error (h^2/24) f'' ~ 3e-10
  // with 20000 points.
  const int n = 20000;
  Real total = 0;
  for (int i = 0; i < n; ++i) {
    const Real t = (i + 0.5) * (pi / 2) / n;
    total +=
        punch.pressure(a * std::sin(t), load) * 2 * pi * a * std::sin(t) * a * std::cos(t) * (pi / 2) / n;
  }
  EXPECT_NEAR(total, load, 1e-8 * load);
  // The incremental stiffness of a Hertz contact of radius a is that of a punch of radius a (Johnson 1985,
  // section 4.2): a central difference of P(delta), error (h^2/6) P''' ~ 1e-8 relative at h = 1e-4 delta.
  const HertzSphere hertz{.radius = 1e-3, .modulus = testing::kPaperModulus};
  const Real hertz_load = hertz.load_of_contact_radius(a), delta = hertz.approach(hertz_load),
             h = 1e-4 * delta;
  const Real slope = (hertz.load_of_approach(delta + h) - hertz.load_of_approach(delta - h)) / (2 * h);
  EXPECT_NEAR(slope, punch.stiffness(), 1e-7 * punch.stiffness());
}

TEST(ReferenceWestergaard, MeanPressureIsTheLoadAndFullContactJoinsContinuously) {
  const WavySurface wavy{.amplitude = 1e-6, .wavelength = 100e-6, .modulus = testing::kPaperModulus};
  const Real p_star = wavy.full_contact_pressure();
  // p* from the half-space's response to one wave: u = 2 p/(E* q), q = 2 pi/lambda, must flatten D.
  EXPECT_NEAR(p_star, testing::kPaperModulus * (2 * pi / wavy.wavelength) * wavy.amplitude / 2,
              1e-15 * p_star);
  for (const Real ratio : {0.1, 0.5, 0.9}) {
    const Real pbar = ratio * p_star, a = wavy.contact_half_width(pbar);
    EXPECT_NEAR(std::pow(std::sin(pi * a / wavy.wavelength), 2), ratio, 1e-15);
    // Over the strip, x = a sin(t) removes the square-root edge: the mean over a wavelength is pbar.
    const Real total = simpson([&](Real t) { return wavy.pressure(a * std::sin(t), pbar) * a * std::cos(t); },
                               -pi / 2, pi / 2, 2000);
    EXPECT_NEAR(total / wavy.wavelength, pbar, 1e-9 * pbar) << ratio;  // measured 1e-13; sin(t) near the edge
    EXPECT_EQ(wavy.pressure(1.001 * a, pbar), 0);
  }
  // Just below p* the strip covers the wavelength and the profile is the full-contact one, p*(1 + cos).
  for (const Real x : {0.0, 10e-6, 30e-6})
    EXPECT_NEAR(wavy.pressure(x, p_star * (1 - 1e-12)), wavy.pressure(x, p_star), 1e-6 * p_star) << x;
}

TEST(ReferenceBisinusoid, FullContactPressureAndSmallLoadAsTwoHertzContacts) {
  const Bisinusoid wave{.amplitude = 1e-6, .wavelength = 100e-6, .modulus = testing::kPaperModulus};
  const Real p_star = wave.full_contact_pressure();
  // One wave of |q| = 2 pi sqrt2/lambda: u = 2 p/(E* |q|) flattens D when the pressure amplitude is p*.
  EXPECT_NEAR(p_star,
              testing::kPaperModulus * (2 * pi * std::sqrt(2.0) / wave.wavelength) * wave.amplitude / 2,
              1e-15 * p_star);
  // Two crests a cell, each of radius lambda^2/(4 pi^2 D), each carrying half the cell's load pbar lambda^2.
  const HertzSphere crest{.radius = wave.wavelength * wave.wavelength / (4 * pi * pi * wave.amplitude),
                          .modulus = testing::kPaperModulus};
  for (const Real ratio : {1e-4, 1e-2}) {
    const Real a = crest.contact_radius(ratio * p_star * wave.wavelength * wave.wavelength / 2);
    const Real two_contacts = 2 * pi * a * a / (wave.wavelength * wave.wavelength);
    EXPECT_NEAR(Bisinusoid::small_load_area_fraction(ratio), two_contacts, 1e-14) << ratio;
  }
  // Near full contact, 1 - A/A0 = (3/(2 pi)) (1 - pbar/p*): the coefficient against its hand value
  // 3/(2 pi) = 0.477464829275686 (at pbar/p* = 1 alone, 1 - 1 = 0 hid the coefficient), and linear in the
  // load. Tolerance 4e-15 relative: one product, and 1 - 0.95 carries 1e-15 relative in double. Rejects a
  // coefficient off by any factor (e.g. 3/(4 pi) or 3/pi) or a power of (1 - pbar/p*) other than 1.
  for (const auto& [ratio, gap] :
       {std::pair<Real, Real>{0.9, 0.0477464829275686}, {0.95, 0.0238732414637843}, {0.5, 0.238732414637843}})
    EXPECT_NEAR(Bisinusoid::near_full_gap_fraction(ratio), gap, 4e-15 * gap) << ratio;
  EXPECT_EQ(Bisinusoid::near_full_gap_fraction(1), 0);
}

}  // namespace
}  // namespace contactbench::reference
