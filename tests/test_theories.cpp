// The analytic theories (docs/theory.md section 5): the Gaussian tail integrals F_n, Greenwood-Williamson
// with McCool's parameters and its load solver, Persson, the BGT linear law. References are computed here by
// independent long double quadrature of the defining integrals, never by the code under test.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/theories/bgt_linear.hpp"
#include "contactbench/theories/brent_root.hpp"
#include "contactbench/theories/gaussian_tail_integrals.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/number_text.hpp"
#include "contactbench/theories/persson.hpp"
#include "test_constants.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

constexpr Real pi = std::numbers::pi;
using testing::nan;

// Named tolerances, each with its reason (docs/architecture.md).
// docs/theory.md prints F_n to 7 significant digits: rounding alone is up to 5e-7 relative.
constexpr Real kTheoryTable = 1e-6;
// F_n against the long double reference quadrature (accurate to ~1e-13): the issue asks for 1e-9; the code
// reaches about 2e-13, limited by the rounding of t^2/2 ~ 800 in double.
constexpr Real kTailReference = 1e-9;
// GW formulas against direct quadrature of the summit integrals (issue: 1e-8).
constexpr Real kGwQuadrature = 1e-8;
// Identities evaluated in a few double operations: a few ulps.
constexpr Real kRoundOff = 1e-14;
// A small-load slope from a finite difference at load 1e-9 sqrt(m2): the curvature term is ~1e-18.
constexpr Real kSlope = 1e-6;

// ---------------------------------------------------------------------------------------------------------------
// Independent reference: adaptive Simpson with Richardson extrapolation in long double (whose exponent range
// holds exp(-800) without underflow), after an initial split into equal panels so that no narrow peak is
// missed.
template <class F>
long double simpson_step(const F& f, long double a, long double b, long double fa, long double fm,
                         long double fb, long double whole, long double tolerance, int depth) {
  const long double m = 0.5L * (a + b), lm = 0.5L * (a + m), rm = 0.5L * (m + b);
  const long double flm = f(lm), frm = f(rm);
  const long double left = (m - a) / 6 * (fa + 4 * flm + fm), right = (b - m) / 6 * (fm + 4 * frm + fb);
  const long double change = left + right - whole;
  if (depth <= 0 || std::abs(change) <= 15 * tolerance) return left + right + change / 15;
  return simpson_step(f, a, m, fa, flm, fm, left, 0.5L * tolerance, depth - 1) +
         simpson_step(f, m, b, fm, frm, fb, right, 0.5L * tolerance, depth - 1);
}

template <class F>
long double integrate(const F& f, long double a, long double b, long double relative_tolerance = 1e-12L) {
  constexpr int panels = 64;
  const long double width = (b - a) / panels;
  // A first pass sets the absolute tolerance from the size of the integral.
  long double estimate = 0;
  for (int i = 0; i < panels; ++i) {
    const long double x0 = a + i * width, x1 = x0 + width;
    estimate += width / 6 * (f(x0) + 4 * f(0.5L * (x0 + x1)) + f(x1));
  }
  const long double tolerance = relative_tolerance * std::abs(estimate) / panels;
  long double sum = 0;
  for (int i = 0; i < panels; ++i) {
    const long double x0 = a + i * width, x1 = x0 + width, xm = 0.5L * (x0 + x1);
    const long double f0 = f(x0), fm = f(xm), f1 = f(x1);
    sum += simpson_step(f, x0, x1, f0, fm, f1, width / 6 * (f0 + 4 * fm + f1), tolerance, 40);
  }
  return sum;
}

// F_n(t) = (2 pi)^(-1/2) int_t^inf (s - t)^n exp(-s^2/2) ds with s = t + w^2 (smooth in w for the n tested):
// = (2 pi)^(-1/2) int_0^inf 2 w^(2n+1) exp(-(t + w^2)^2/2) dw, cut where the integrand is below e^-60 of its
// peak. n is a multiple of 1/2, so that w^(2n+1) is a product (powl would dominate the cost).
long double reference_tail(Real n, Real t) {
  const long double tl = t;
  const int power = static_cast<int>(2 * n + 1);
  auto f = [tl, power](long double w) {
    const long double s = tl + w * w;
    long double w_power = 2;
    for (int i = 0; i < power; ++i)
      w_power *= w;
    return w_power * std::exp(-0.5L * s * s);
  };
  const long double w2 = (t < 0 ? -tl : 0.0L) + (t > 1 ? 80.0L / tl : 13.0L);
  return integrate(f, 0.0L, std::sqrt(w2)) / std::sqrt(2 * std::numbers::pi_v<long double>);
}

// ---------------------------------------------------------------------------------------------------------------
// F_n

TEST(GaussianTailIntegrals, MatchTheTableOfTheoryMd) {
  struct Row {
    Real t, f0, f1, f32;
  };
  // docs/theory.md section 5, "checks".
  const Row rows[] = {{0, 0.5, 0.3989423, 0.4300200},
                      {1, 0.1586553, 0.08331547, 0.07566818},
                      {2.5, 6.209665e-3, 2.004137e-3, 1.469938e-3},
                      {4, 3.167124e-5, 7.145258e-6, 4.439156e-6}};
  for (const Row& r : rows) {
    // Tolerance kTheoryTable: the table's 7 printed digits.
    EXPECT_NEAR(gaussian_tail_integral(0, r.t), r.f0, kTheoryTable * r.f0) << "F_0(" << r.t << ")";
    EXPECT_NEAR(gaussian_tail_integral(1, r.t), r.f1, kTheoryTable * r.f1) << "F_1(" << r.t << ")";
    EXPECT_NEAR(gaussian_tail_integral(1.5, r.t), r.f32, kTheoryTable * r.f32) << "F_3/2(" << r.t << ")";
  }
}

TEST(GaussianTailIntegrals, MatchLongDoubleQuadratureOverTheWholeRange) {
  std::vector<Real> ts;
  for (int i = 0; i <= 100; ++i)
    ts.push_back(-10 + 0.5 * i);
  // Both sides of where the closed forms hand over to the quadrature (t = 1 for F_1, t = 2 for F_0).
  for (const Real t : {1 - 1e-9, 1 + 1e-9, 2 - 1e-9, 2 + 1e-9, 0.3, 7.77, 38.6})
    ts.push_back(t);
  for (const Real n : {0.0, 0.5, 1.0, 1.5, 2.5})
    for (const Real t : ts) {
      const long double reference = reference_tail(n, t);
      ASSERT_GT(reference, 0.0L);
      // In logarithms, because F underflows double beyond t ~ 38: |d ln F| = relative error of F.
      // Tolerance kTailReference (issue: 1e-9).
      EXPECT_NEAR(log_gaussian_tail_integral(n, t), static_cast<Real>(std::log(reference)), kTailReference)
          << "n = " << n << ", t = " << t;
      if (reference > 1e-300L) {
        EXPECT_NEAR(gaussian_tail_integral(n, t), static_cast<Real>(reference),
                    kTailReference * static_cast<Real>(reference))
            << "n = " << n << ", t = " << t;
      }
    }
}

TEST(GaussianTailIntegrals, LogIsFiniteWhereTheValueUnderflows) {
  for (const Real n : {0.0, 1.0, 1.5}) {
    const Real log_f = log_gaussian_tail_integral(n, 40);
    EXPECT_TRUE(std::isfinite(log_f)) << "n = " << n;
    // ln F_n(40) ~ -800 - (n + 1) ln 40 - ln sqrt(2 pi) (the leading asymptotics, good to ~1e-3 here).
    EXPECT_NEAR(log_f, -800 - (n + 1) * std::log(40.0) + std::lgamma(n + 1) - 0.5 * std::log(2 * pi), 0.01);
    for (Real t = 30; t <= 40; t += 0.125) {
      const Real f = gaussian_tail_integral(n, t);
      EXPECT_FALSE(std::isnan(f)) << "n = " << n << ", t = " << t;
      EXPECT_GE(f, 0) << "n = " << n << ", t = " << t;
    }
    const Real f40 = gaussian_tail_integral(n, 40);
    EXPECT_TRUE(f40 == 0 || std::fpclassify(f40) == FP_SUBNORMAL) << f40;
  }
}

TEST(GaussianTailIntegrals, DecreaseStrictlyInT) {
  for (const Real n : {0.0, 1.0, 1.5}) {
    Real previous = log_gaussian_tail_integral(n, -10);
    for (int i = 1; i <= 2500; ++i) {
      const Real t = -10 + 0.02 * i;
      const Real current = log_gaussian_tail_integral(n, t);
      // Strictly below t = -8 only where F differs from 1 in double (F_0(-8) = 1 - 6e-16).
      if (t > -8)
        ASSERT_LT(current, previous) << "n = " << n << ", t = " << t;
      else
        ASSERT_LE(current, previous) << "n = " << n << ", t = " << t;
      previous = current;
    }
  }
}

TEST(GaussianTailIntegrals, RefuseBadArguments) {
  EXPECT_THROW(gaussian_tail_integral(-0.5, 1), Error);
  EXPECT_THROW(gaussian_tail_integral(nan, 1), Error);
  EXPECT_THROW(log_gaussian_tail_integral(1.5, nan), Error);
  EXPECT_THROW(log_gaussian_tail_integral(1.5, std::numeric_limits<Real>::infinity()), Error);
}

// ---------------------------------------------------------------------------------------------------------------
// Greenwood-Williamson with McCool's parameters

// The paper's surface A, Table 2 (docs/theory.md section 2), in SI.
SpectralMoments table2_surface_a() {
  return {.m0 = 0.250e-12, .m2x = 0.0110, .m4x = 0.0446e12, .m2y = 0.0110, .m4y = 0.0446e12};
}

SpectralMoments generated_surface_a_moments() {
  return spectral_moments(generate_surface(paper::grid(), paper::surface_a(), 20240611, 1));
}

// N/A0, A/A0, P/(E* A0) straight from Greenwood & Williamson's integrals over summit heights z > d with the
// Gaussian density phi_s of mean ys and deviation sigma_s, in SI, with z = d + v^2 to smooth (z - d)^(3/2).
struct GwIntegrals {
  long double spots, area, load;
};
GwIntegrals gw_by_quadrature(const GwParameters& gw, Real d) {
  const long double ys = gw.ys, s = gw.sigma_s, dl = d;
  auto density = [ys, s](long double z) {
    const long double x = (z - ys) / s;
    return std::exp(-0.5L * x * x) / (s * std::sqrt(2 * std::numbers::pi_v<long double>));
  };
  // Up to 12 sigma_s above the larger of d and ys: the density has fallen below e^-72 there.
  const long double v_max = std::sqrt(std::max(0.0L, ys - dl) + 12 * s);
  auto over = [&](auto power) {
    return integrate([&](long double v) { return 2 * v * power(v * v) * density(dl + v * v); }, 0.0L, v_max);
  };
  const long double eta = gw.eta, beta = gw.beta;
  GwIntegrals r;
  r.spots = eta * over([](long double) { return 1.0L; });
  r.area = std::numbers::pi_v<long double> * eta * beta * over([](long double u) { return u; });
  r.load = 4.0L / 3.0L * eta * std::sqrt(beta) * over([](long double u) { return u * std::sqrt(u); });
  return r;
}

TEST(GreenwoodWilliamson, MatchesDirectQuadratureOfTheSummitIntegrals) {
  const GwParameters gw = mccool_parameters(table2_surface_a());
  for (const Real t : {-3.0, -0.5, 0.0, 1.3, 3.0, 6.0}) {
    const Real d = gw_separation(gw, t);
    const GwIntegrals want = gw_by_quadrature(gw, d);
    const Real t_back = (d - gw.ys) / gw.sigma_s;
    // Tolerance kGwQuadrature (issue: 1e-8); the round trip t -> d -> t costs ~1e-15.
    EXPECT_NEAR(gw_spot_density(gw, t_back), static_cast<Real>(want.spots), kGwQuadrature * want.spots) << t;
    EXPECT_NEAR(gw_area_fraction(gw, t_back), static_cast<Real>(want.area), kGwQuadrature * want.area) << t;
    EXPECT_NEAR(gw_load(gw, t_back), static_cast<Real>(want.load), kGwQuadrature * want.load) << t;
  }
}

void expect_mccool_identities(const SpectralMoments& moments) {
  const GwParameters gw = mccool_parameters(moments);
  const Real m0 = moments.m0, m2 = 0.5 * (moments.m2x + moments.m2y), m4 = 0.5 * (moments.m4x + moments.m4y);
  const Real alpha = m0 * m4 / (m2 * m2);
  // Each identity is a rearrangement of McCool's formulas: round-off only (kRoundOff).
  EXPECT_NEAR(gw.eta, m4 / (6 * pi * std::sqrt(3.0) * m2), kRoundOff * gw.eta);
  EXPECT_NEAR(gw.eta, alpha * m2 / (6 * pi * std::sqrt(3.0) * m0), kRoundOff * gw.eta);  // via alpha
  EXPECT_NEAR(gw.beta * gw.beta * m4, 9 * pi / 64, kRoundOff);                           // beta^2 m4
  EXPECT_NEAR(gw.ys, 4 * m2 / std::sqrt(pi * m4), kRoundOff * gw.ys);
  EXPECT_NEAR(gw.ys, 32 / (3 * pi) * gw.beta * m2, kRoundOff * gw.ys);  // ys from beta
  EXPECT_NEAR(gw.sigma_s * gw.sigma_s, m0 - 0.8968 * m2 * m2 / m4, kRoundOff * m0);
  for (const Real v : {gw.eta, gw.beta, gw.sigma_s, gw.ys}) {
    EXPECT_TRUE(std::isfinite(v));
    EXPECT_GT(v, 0);
  }
  EXPECT_LT(gw.sigma_s, std::sqrt(m0));
}

TEST(GreenwoodWilliamson, McCoolParametersObeyTheirIdentities) {
  expect_mccool_identities(table2_surface_a());
  expect_mccool_identities(generated_surface_a_moments());
  // Surface A, Table 2: eta = 0.0446e12 / (6 pi sqrt3 0.0110) = 1.24188e11 1/m^2 (hand computation).
  EXPECT_NEAR(mccool_parameters(table2_surface_a()).eta, 1.24188e11, 1e-5 * 1.24188e11);
}

std::vector<Real> log_spaced(Real first, Real last, int count) {
  std::vector<Real> v;
  for (int i = 0; i < count; ++i)
    v.push_back(first * std::pow(last / first, static_cast<Real>(i) / (count - 1)));
  v.back() = last;
  return v;
}

void expect_monotone(const LoadAreaCurve& curve) {
  ASSERT_EQ(curve.area_fraction.size(), curve.load.size());
  for (std::size_t i = 1; i < curve.load.size(); ++i) {
    EXPECT_GE(curve.load[i], curve.load[i - 1]) << curve.method << " row " << i;
    EXPECT_GE(curve.area_fraction[i], curve.area_fraction[i - 1]) << curve.method << " row " << i;
  }
  for (const Real a : curve.area_fraction) {
    EXPECT_GT(a, 0) << curve.method;
    EXPECT_LE(a, 1) << curve.method;
  }
}

Real capped_from(const std::string& parameters) {
  const std::string key = "capped at A/A0 = 1 for loads >= ";
  const std::size_t at = parameters.find(key);
  return at == std::string::npos ? nan : std::stod(parameters.substr(at + key.size()));
}

TEST(GreenwoodWilliamson, SolverReproducesTheRequestedLoadsAndCapsTheArea) {
  const SpectralMoments moments = generated_surface_a_moments();
  const GwParameters gw = mccool_parameters(moments);
  const Real largest = gw_load(gw, kGwMinSeparation);
  const std::vector<Real> loads = log_spaced(1e-8, 0.9 * largest, 60);
  const LoadAreaCurve curve = gw_mccool_curve(moments, loads);
  EXPECT_EQ(curve.method, "gw_mccool");
  ASSERT_EQ(curve.load.size(), loads.size());
  ASSERT_EQ(curve.separation.size(), loads.size());
  ASSERT_EQ(curve.spots.size(), loads.size());
  expect_monotone(curve);
  const Real cap = capped_from(curve.parameters);
  ASSERT_TRUE(std::isfinite(cap)) << "GW exceeds A/A0 = 1 below 0.9 of its largest load: "
                                  << curve.parameters;
  EXPECT_NE(curve.parameters.find("means of x and y"), std::string::npos) << curve.parameters;
  EXPECT_NE(curve.parameters.find("eta = "), std::string::npos) << curve.parameters;
  for (std::size_t i = 0; i < loads.size(); ++i) {
    EXPECT_NEAR(curve.load[i], loads[i], tolerance::solved_load * loads[i]) << "row " << i;
    // The separation is d = ys + t sigma_s, and GW's own area there decides the cap.
    const Real t = (curve.separation[i] - gw.ys) / gw.sigma_s;
    const Real uncapped = gw_area_fraction(gw, t);
    if (uncapped > 1) {
      EXPECT_EQ(curve.area_fraction[i], 1) << "row " << i;
      EXPECT_GE(loads[i], cap * (1 - 1e-5)) << "row " << i;  // cap printed to 6 digits
    } else {
      // Tolerance 1e-9: t recovered from d in double costs ~1e-15 relative, times d ln A/dt ~ 10.
      EXPECT_NEAR(curve.area_fraction[i], uncapped, 1e-9 * uncapped) << "row " << i;
      EXPECT_LE(loads[i], cap * (1 + 1e-5)) << "row " << i;
    }
    EXPECT_TRUE(std::isnan(curve.spots[i]));
  }
  EXPECT_EQ(curve.area_fraction.back(), 1);  // the large-load limit: full contact (capped)
  EXPECT_LT(curve.area_fraction.front(), 1e-6);
  // Separations fall as the load rises.
  for (std::size_t i = 1; i < loads.size(); ++i)
    EXPECT_LT(curve.separation[i], curve.separation[i - 1]);
}

TEST(GreenwoodWilliamson, AreaVanishesWithTheLoadAndSpotsNeedTheNominalArea) {
  const SpectralMoments moments = table2_surface_a();
  const GwParameters gw = mccool_parameters(moments);
  const Real a0 = paper::grid().nominal_area();
  const std::vector<Real> loads = {1e-14, 1e-12, 1e-10};
  const LoadAreaCurve curve = gw_mccool_curve(moments, loads, a0);
  EXPECT_EQ(curve.parameters.find("capped"), std::string::npos) << curve.parameters;
  for (std::size_t i = 0; i < loads.size(); ++i) {
    EXPECT_GT(curve.area_fraction[i], 0);
    EXPECT_LT(curve.area_fraction[i], 1e3 * loads[i]);  // A/A0 -> 0 with the load (kappa-like ratio < 1e3)
    const Real t = (curve.separation[i] - gw.ys) / gw.sigma_s;
    // Tolerance 1e-12: t recovered from d in double, times d ln F_0/dt ~ t.
    EXPECT_NEAR(curve.spots[i], gw_spot_density(gw, t) * a0, 1e-12 * curve.spots[i]);
  }
}

TEST(GreenwoodWilliamson, RefusesLoadsBeyondReachAndBadInput) {
  const SpectralMoments moments = table2_surface_a();
  const GwParameters gw = mccool_parameters(moments);
  const Real largest = gw_load(gw, kGwMinSeparation);
  const std::vector<Real> too_large = {0.5 * largest, 2 * largest};
  try {
    gw_mccool_curve(moments, too_large);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(format_number(2 * largest)), std::string::npos) << message;
    EXPECT_NE(message.find("largest load reachable, " + format_number(largest)), std::string::npos)
        << message;
  }
  for (const Real bad : {-1e-3, 0.0, nan}) {
    const std::vector<Real> loads = {1e-6, bad};
    try {
      gw_mccool_curve(moments, loads);
      ADD_FAILURE() << "no error for " << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("got " + format_number(bad)), std::string::npos) << e.what();
    }
  }
  const std::vector<Real> descending = {1e-3, 1e-4};
  EXPECT_THROW(gw_mccool_curve(moments, descending), Error);
  EXPECT_THROW(gw_solve_separation(gw, -1), Error);
  EXPECT_THROW(validate(GwParameters{.eta = 1, .beta = -1, .sigma_s = 1, .ys = 0}), Error);
}

TEST(GreenwoodWilliamson, RefusesAlphaAtOrBelowNayaksBound) {
  // alpha = m0 m4/m2^2 = 0.8 <= 0.8968: sigma_s^2 = (1 - 0.8968/alpha) m0 < 0.
  const SpectralMoments m{.m0 = 1e-12, .m2x = 1e-2, .m4x = 0.8e8, .m2y = 1e-2, .m4y = 0.8e8};
  try {
    mccool_parameters(m);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("alpha"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("0.8968"), std::string::npos) << e.what();
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Anisotropy and bad moments, for every theory

TEST(MomentTheories, RefuseAnisotropicSurfacesNamingTheMoments) {
  const std::vector<Real> loads = {1e-3};
  SpectralMoments m2_aniso = table2_surface_a();
  m2_aniso.m2x *= 1.2;
  SpectralMoments m4_aniso = table2_surface_a();
  m4_aniso.m4y *= 1.1;
  auto expect_refused = [](auto&& call, const std::string& a, const std::string& b,
                           const std::string& ratio) {
    try {
      call();
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      const std::string message = e.what();
      for (const std::string& word : {a, b, ratio, std::string("anisotropic")})
        EXPECT_NE(message.find(word), std::string::npos) << word << " not in: " << message;
    }
  };
  expect_refused([&] { gw_mccool_curve(m2_aniso, loads); }, "m2x", "m2y", "m2x/m2y = 1.2");
  expect_refused([&] { persson_curve(m2_aniso, loads); }, "m2x", "m2y", "m2x/m2y = 1.2");
  expect_refused([&] { bgt_linear_curve(m2_aniso, loads); }, "m2x", "m2y", "m2x/m2y = 1.2");
  expect_refused([&] { mccool_parameters(m4_aniso); }, "m4x", "m4y", "m4x/m4y = 0.909091");
  // Persson and the BGT linear law use m2 only: an m4 anisotropy does not concern them.
  EXPECT_NO_THROW(persson_curve(m4_aniso, loads));
  EXPECT_NO_THROW(bgt_linear_curve(m4_aniso, loads));
  // Within 5 % is accepted, as the mean.
  SpectralMoments slight = table2_surface_a();
  slight.m2x *= 1.04;
  EXPECT_NEAR(isotropic_m2(slight, "test"), 0.0110 * 1.02, kRoundOff);
}

TEST(MomentTheories, RefuseNonPositiveOrNonFiniteMoments) {
  const std::vector<Real> loads = {1e-3};
  for (const Real bad : {0.0, -1.0, nan}) {
    SpectralMoments m = table2_surface_a();
    m.m0 = bad;
    EXPECT_THROW(gw_mccool_curve(m, loads), Error) << bad;
    m = table2_surface_a();
    m.m2x = m.m2y = bad;
    EXPECT_THROW(persson_curve(m, loads), Error) << bad;
    EXPECT_THROW(bgt_linear_curve(m, loads), Error) << bad;
    EXPECT_THROW(gw_mccool_curve(m, loads), Error) << bad;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Persson

TEST(Persson, MomentAndPsdFormsAgree) {
  // Synthetic: int q^3 C dq = m2/pi for an isotropic continuum (docs/theory.md section 1).
  const Real m2 = 0.0110;
  for (const Real load : {1e-6, 1e-3, 0.05, 0.1, 0.3}) {
    const Real a = persson_area_fraction(load, m2);
    // Tolerance kRoundOff: the same number through a few different operations.
    EXPECT_NEAR(persson_area_fraction_psd(load, m2 / pi), a, kRoundOff * a) << load;
  }
  // On the lattice: the PSD summed with |q|^2 against the profile moments summed with qx^2 and qy^2.
  const Surface surface = generate_surface(paper::grid(), paper::surface_a(), 20240611, 1);
  const FourierCoefficients c = fourier_coefficients(surface);
  const SpectralMoments moments = spectral_moments(c);
  const Real m2_lattice = isotropic_m2(moments, "test");
  const Real q3 = persson_q3_integral(c);
  // Tolerance kRoundOff: two summation orders of the same 32k terms.
  EXPECT_NEAR(q3 * pi, m2_lattice, kRoundOff * m2_lattice);
  for (const Real load : {1e-6, 1e-3, 0.05, 0.1}) {
    const Real a = persson_area_fraction(load, m2_lattice);
    EXPECT_NEAR(persson_area_fraction_psd(load, q3), a, kRoundOff * a) << load;
  }
}

TEST(Persson, SmallLoadSlopeIsSqrt8OverPiOverGbarAndFullContactAtLargeLoad) {
  const SpectralMoments moments = generated_surface_a_moments();
  const Real gbar = moments.rms_gradient();  // areal: sqrt(m2x + m2y)
  const Real m2 = isotropic_m2(moments, "test");
  const Real load = 1e-9 * std::sqrt(m2);
  // Tolerance kSlope: erf(x)/x = (2/sqrt(pi))(1 - x^2/3 + ...), x = 1e-9.
  EXPECT_NEAR(persson_area_fraction(load, m2) / load, std::sqrt(8 / pi) / gbar,
              kSlope * std::sqrt(8 / pi) / gbar);
  // Away from the slope: A/A0 = erf(p/(E* sqrt(m2))) against erf values from tables (Abramowitz & Stegun
  // 7.1, 10 digits), so a wrong factor inside the erf (sqrt2, the areal gbar for the isotropic m2, a factor
  // 2 in G) shows where erf is curved. Tolerance 1e-10 absolute: the tabulated digits; std::erf is exact to a
  // few ulp. (Before: sqrt(8/pi) against 1.596, one constant against another, which nothing could change.)
  // Rejects the argument scaled by 1 + 1e-3 (a change of ~4e-4 at x = 0.5) or by sqrt2.
  for (const auto& [x, erf_x] : {std::pair<Real, Real>{0.25, 0.2763263902},
                                 {0.5, 0.5204998778},
                                 {1.0, 0.8427007929},
                                 {2.0, 0.9953222650}})
    EXPECT_NEAR(persson_area_fraction(x * std::sqrt(m2), m2), erf_x, 1e-10) << x;
  // erf(10) = 1 in double.
  EXPECT_EQ(persson_area_fraction(10 * std::sqrt(m2), m2), 1);

  const std::vector<Real> loads = log_spaced(1e-8, 10 * std::sqrt(m2), 40);
  const LoadAreaCurve curve = persson_curve(moments, loads);
  EXPECT_EQ(curve.method, "persson");
  EXPECT_NE(curve.parameters.find("mean of m2x and m2y"), std::string::npos) << curve.parameters;
  expect_monotone(curve);
  EXPECT_EQ(curve.load, loads);
  EXPECT_LT(curve.area_fraction.front(), 1e-6);
  EXPECT_EQ(curve.area_fraction.back(), 1);
  for (std::size_t i = 0; i < loads.size(); ++i) {
    EXPECT_TRUE(std::isnan(curve.separation[i]));
    EXPECT_TRUE(std::isnan(curve.spots[i]));
  }
}

// ---------------------------------------------------------------------------------------------------------------
// BGT linear law

TEST(BgtLinear, SlopeIsSqrt2PiOverGbarAndTheCapIsNamed) {
  const SpectralMoments moments = generated_surface_a_moments();
  const Real gbar = moments.rms_gradient();
  const Real m2 = isotropic_m2(moments, "test");
  for (const Real load : {1e-9, 1e-4, 0.01}) {
    // "Exactly" up to the round-off of sqrt(pi/m2) against sqrt(2 pi)/sqrt(2 m2): kRoundOff.
    EXPECT_NEAR(bgt_linear_area_fraction(load, m2) / load, std::sqrt(2 * pi) / gbar,
                kRoundOff * std::sqrt(2 * pi) / gbar);
  }
  const Real full = bgt_linear_full_contact_load(m2);
  EXPECT_NEAR(bgt_linear_area_fraction(full, m2), 1, kRoundOff);

  const std::vector<Real> below = log_spaced(1e-8, 0.5 * full, 10);
  const LoadAreaCurve uncapped = bgt_linear_curve(moments, below);
  EXPECT_EQ(uncapped.method, "bgt_linear");
  EXPECT_TRUE(std::isnan(capped_from(uncapped.parameters))) << uncapped.parameters;
  EXPECT_NE(uncapped.parameters.find("mean of m2x and m2y"), std::string::npos) << uncapped.parameters;

  const std::vector<Real> loads = log_spaced(1e-8, 3 * full, 30);
  const LoadAreaCurve curve = bgt_linear_curve(moments, loads);
  expect_monotone(curve);
  EXPECT_EQ(curve.area_fraction.back(), 1);
  EXPECT_LT(curve.area_fraction.front(), 1e-6);
  // The cap's load is printed to 6 digits.
  EXPECT_NEAR(capped_from(curve.parameters), full, 1e-5 * full) << curve.parameters;
  for (std::size_t i = 0; i < loads.size(); ++i)
    EXPECT_EQ(curve.area_fraction[i], std::min<Real>(1, bgt_linear_area_fraction(loads[i], m2))) << i;
}

TEST(LoadSolver, BrentFindsRootsOfMonotoneFunctions) {
  auto f = [](Real x) { return std::exp(x) - 2; };
  // Tolerance 1e-15 absolute in f: what was asked of find_root.
  const Real root = find_root(f, -10, 10, f(-10), f(10), 1e-15, 0);
  EXPECT_NEAR(root, std::log(2.0), 1e-15);
  EXPECT_THROW(find_root(f, 1, 10, f(1), f(10), 1e-15, 0), Error);
}

}  // namespace
}  // namespace contactbench
