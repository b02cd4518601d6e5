// Spectra and moments (docs/theory.md section 1): conventions checked on fields whose moments are known
// exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <numeric>
#include <random>

#include "contactbench/core/spectrum.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

// h = a cos(qx x + qy y + phase) on a periodic grid, with (kx, ky) lattice indices.
Surface plane_wave(const Grid& grid, Real a, Index kx, Index ky, Real phase = 0.3) {
  HeightMap h(grid.ny, grid.nx);
  for (Index iy = 0; iy < grid.ny; ++iy)
    for (Index ix = 0; ix < grid.nx; ++ix)
      h(iy, ix) =
          a *
          std::cos(2 * pi * (static_cast<Real>(kx * ix) / grid.nx + static_cast<Real>(ky * iy) / grid.ny) +
                   phase);
  return Surface(grid, h);
}

Surface white_noise(const Grid& grid, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<Real> normal(0.0, 1e-6);
  HeightMap h(grid.ny, grid.nx);
  for (Index i = 0; i < h.size(); ++i)
    h.data()[i] = normal(random);
  return Surface(grid, h);
}

const Grid kRectangular{.nx = 48, .ny = 30, .lx = 96e-6, .ly = 45e-6, .periodic = true};

TEST(SpectralMoments, OfAPlaneWaveAreItsWavevectorPowers) {
  const Real a = 2e-6;
  const Index kx = 5, ky = -3;
  const SpectralMoments m = spectral_moments(plane_wave(kRectangular, a, kx, ky));
  const Real qx = kRectangular.dqx() * kx, qy = kRectangular.dqy() * ky;
  const Real m0 = a * a / 2;
  // Exact on the lattice: only round-off of one FFT, relative 1e-12 is generous.
  EXPECT_NEAR(m.m0, m0, tolerance::fft_round_off * m0);
  EXPECT_NEAR(m.m2x, qx * qx * m0, tolerance::fft_round_off * qx * qx * m0);
  EXPECT_NEAR(m.m4x, std::pow(qx, 4) * m0, tolerance::fft_round_off * std::pow(qx, 4) * m0);
  EXPECT_NEAR(m.m2y, qy * qy * m0, tolerance::fft_round_off * qy * qy * m0);
  EXPECT_NEAR(m.m4y, std::pow(qy, 4) * m0, tolerance::fft_round_off * std::pow(qy, 4) * m0);
  EXPECT_NEAR(m.rms_gradient(), std::hypot(qx, qy) * a / std::sqrt(2.0), 1e-12 * std::hypot(qx, qy) * a);
}

TEST(SpectralMoments, NyquistModesCountOnce) {
  // A checkerboard a (-1)^(ix+iy) is the single mode (Nx/2, Ny/2): m2x = (pi/dx)^2 a^2, not twice that.
  const Real a = 1e-6;
  const SpectralMoments m = spectral_moments(plane_wave(kRectangular, a, 24, 15, 0.0));
  const Real qx = pi / kRectangular.dx();
  EXPECT_NEAR(m.m0, a * a, 1e-12 * a * a);
  EXPECT_NEAR(m.m2x, qx * qx * a * a, 1e-12 * qx * qx * a * a);
}

TEST(SpectralMoments, M0IsTheVarianceAndGradientsMatchTheContinuumOperators) {
  // Parseval on a periodic lattice: m0 equals the variance about the mean exactly (to round-off).
  const Surface s = white_noise(kRectangular, 1);
  const SpectralMoments m = spectral_moments(s);
  EXPECT_NEAR(m.m0, std::pow(s.rms_height(), 2), 1e-12 * m.m0);
  EXPECT_NEAR(std::sqrt(m.m0), m.rms_height(), 1e-12 * std::sqrt(m.m0));
  EXPECT_GT(m.alpha_x(), 1.0);  // alpha >= 1 for any spectrum (Cauchy-Schwarz); white noise is broad
}

TEST(ProfilePsd, SumsToTheMomentsAlongEachAxis) {
  const FourierCoefficients c = fourier_coefficients(white_noise(kRectangular, 2));
  const SpectralMoments m = spectral_moments(c);
  for (const bool along_x : {true, false}) {
    const SampledPsd p = along_x ? profile_psd_x(c) : profile_psd_y(c);
    const Index n = along_x ? kRectangular.nx : kRectangular.ny;
    const Real dq = along_x ? kRectangular.dqx() : kRectangular.dqy();
    Real m0 = 0, m2 = 0;
    for (std::size_t i = 0; i < p.q.size(); ++i) {
      // Two-sided: every listed q > 0 stands for +q and -q, except Nyquist (even n) and q = 0.
      const bool single = i == 0 || (n % 2 == 0 && static_cast<Index>(i) == n / 2);
      const Real weight = (single ? 1.0 : 2.0) * dq;
      m0 += weight * p.c[i];
      m2 += weight * p.q[i] * p.q[i] * p.c[i];
    }
    // Both are regroupings of the same lattice sum: round-off only.
    EXPECT_NEAR(m0, m.m0, 1e-12 * m.m0) << (along_x ? "x" : "y");
    EXPECT_NEAR(m2, along_x ? m.m2x : m.m2y, 1e-12 * m2) << (along_x ? "x" : "y");
  }
}

TEST(RadialPsd, HasNoEmptyOrNanBinsAndAccountsForEveryMode) {
  const FourierCoefficients c = fourier_coefficients(white_noise(kRectangular, 3));
  const SampledPsd p = radial_psd(c, 10);
  ASSERT_GT(p.q.size(), 5u);
  for (std::size_t i = 0; i < p.q.size(); ++i) {
    EXPECT_TRUE(std::isfinite(p.q[i]) && std::isfinite(p.c[i])) << i;
    EXPECT_GT(p.modes[i], 0) << i;
    if (i > 0) {
      EXPECT_GT(p.q[i], p.q[i - 1]) << i;
    }
  }
  // Every lattice mode but the mean lies in exactly one bin.
  EXPECT_EQ(std::accumulate(p.modes.begin(), p.modes.end(), Index{0}), kRectangular.points() - 1);
  // Sum of the bin means weighted by their mode counts is the 2D PSD's integral: m0.
  Real integral = 0;
  for (std::size_t i = 0; i < p.q.size(); ++i)
    integral += p.c[i] * static_cast<Real>(p.modes[i]) * kRectangular.dqx() * kRectangular.dqy();
  EXPECT_NEAR(integral, spectral_moments(c).m0, 1e-12 * integral);
}

TEST(Window, HannRemovesTheEdgeJumpOfANonPeriodicRecord) {
  // A sine with 10.37 periods across the record: not periodic on the grid. Without a window the jump at the
  // edge adds a q^-2 tail to the PSD and inflates m2; with the Hann window m2 comes out close to q^2 a^2 / 2.
  const Index n = 256;
  const Grid grid{.nx = n, .ny = 8, .lx = 1e-3, .ly = 1e-3 * 8 / n, .periodic = false};
  const Real a = 1e-6, q = 2 * pi * 10.37 / grid.lx;
  HeightMap h(grid.ny, grid.nx);
  for (Index iy = 0; iy < grid.ny; ++iy)
    for (Index ix = 0; ix < grid.nx; ++ix)
      h(iy, ix) = a * std::sin(q * ix * grid.dx());
  const Surface s(grid, h);
  const Real expected_m2 = q * q * a * a / 2, expected_m4 = q * q * expected_m2;
  const SpectralMoments windowed = spectral_moments(fourier_coefficients(s, Window::hann));
  const SpectralMoments raw = spectral_moments(fourier_coefficients(s, Window::none));
  EXPECT_EQ(fourier_coefficients(s).window, Window::hann);  // the default for a non-periodic surface
  // The window spreads the line over a few dq around q, a bias of order (dq/q)^2 = 1 % in m2 and a few %
  // in m4 (measured: 0.3 % and 1.9 %): allow 2 % and 5 %.
  EXPECT_NEAR(windowed.m2x, expected_m2, 0.02 * expected_m2);
  EXPECT_NEAR(windowed.m4x, expected_m4, 0.05 * expected_m4);
  // What the window is there to prevent: the edge jump's q^-2 tail multiplies m4 (measured: 10.8 times).
  EXPECT_GT(raw.m4x, 3 * expected_m4);
}

}  // namespace
}  // namespace contactbench
