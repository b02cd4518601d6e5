// The elastic half-space operators (docs/theory.md section 6), checked before any solver relies on them:
// Love's kernel against its closed-form values, the non-periodic operator against a direct sum of kernels,
// the periodic operator against single Fourier modes, and reciprocity (a symmetric, positive operator).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/bem/love_kernel.hpp"
#include "contactbench/core/error.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

HeightMap random_pressure(Index nx, Index ny, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<Real> uniform(0, 1e8);
  HeightMap p(ny, nx);
  for (Index i = 0; i < p.size(); ++i)
    p.data()[i] = uniform(random);
  return p;
}

TEST(LoveKernel, CentreOfASquareIsTheClosedForm) {
  // docs/theory.md section 7: centre of a square of side s: u = (4 ln(1 + sqrt2)/pi) p s/E* = 1.122200 p
  // s/E*.
  const Real s = 2e-6;
  const Real expected = 4 * std::log(1 + std::sqrt(2.0)) / pi * s;
  EXPECT_NEAR(love_displacement(0, 0, s / 2, s / 2), expected, 1e-14 * expected);  // round-off of 8 logs
  EXPECT_NEAR(expected / s, 1.122200, 5e-7);  // the printed value has 7 digits
}

TEST(LoveKernel, CornerIsHalfTheCentreOfTheDoubleSquare) {
  // Superposition: the centre of a 2s square is the sum of four s squares at their corners, so the corner of
  // one square carries a quarter of it; a check of the formula's signs away from the centre.
  const Real s = 1e-6;
  EXPECT_NEAR(love_displacement(s / 2, s / 2, s / 2, s / 2), love_displacement(0, 0, s, s) / 4,
              1e-14 * love_displacement(0, 0, s, s));
}

TEST(LoveKernel, FarFieldIsBoussinesqsPointLoad) {
  // At distance r from a pixel of area s^2 the displacement tends to s^2/(pi r) (Boussinesq, E* = 1, p = 1);
  // the relative correction is of order (s/r)^2 / 24 (the square's second moment): under 1e-4 at r = 50 s.
  const Real s = 1e-6;
  for (const Real r : {50 * s, 200 * s}) {
    const Real point = s * s / (pi * r);
    EXPECT_NEAR(love_displacement(r, 0, s / 2, s / 2), point, 1e-4 * point) << r / s;
    EXPECT_NEAR(love_displacement(0.6 * r, 0.8 * r, s / 2, s / 2), point, 1e-4 * point) << r / s;
  }
}

TEST(LoveKernel, IsEvenAndFiniteOnTheEdges) {
  const Real a = 1e-6, b = 0.5e-6;
  for (const Real x : {0.0, a, 2 * a, 10 * a})
    for (const Real y : {0.0, b, 3 * b}) {
      const Real u = love_displacement(x, y, a, b);
      EXPECT_TRUE(std::isfinite(u) && u > 0) << x << ", " << y;
      // Evenness in x and y, up to the order of the terms: away from the pixel the four terms are each of
      // order a ln(r/a) but sum to order a^2/r, so round-off grows by about (r/a) ln(r/a), ~50 at r = 10 a.
      EXPECT_NEAR(love_displacement(-x, y, a, b), u, 1e-12 * u);
      EXPECT_NEAR(love_displacement(x, -y, a, b), u, 1e-12 * u);
    }
}

TEST(NonPeriodicHalfSpace, EqualsTheDirectSumOfLoveKernels) {
  // Rectangular pixels, a non-square grid: the FFT convolution must equal the O(n^2) sum to round-off.
  const Grid grid{.nx = 12, .ny = 9, .lx = 12e-6, .ly = 13.5e-6, .periodic = false};
  const HeightMap p = random_pressure(grid.nx, grid.ny, 1);
  HeightMap u;
  make_nonperiodic_half_space(grid, testing::kPaperModulus)->apply(p, u);
  const Real dx = grid.dx(), dy = grid.dy();
  Real worst = 0, scale = 0;
  for (Index iy = 0; iy < grid.ny; ++iy)
    for (Index ix = 0; ix < grid.nx; ++ix) {
      Real direct = 0;
      for (Index jy = 0; jy < grid.ny; ++jy)
        for (Index jx = 0; jx < grid.nx; ++jx)
          direct += p(jy, jx) * love_displacement((ix - jx) * dx, (iy - jy) * dy, dx / 2, dy / 2) /
                    testing::kPaperModulus;
      worst = std::max(worst, std::abs(u(iy, ix) - direct));
      scale = std::max(scale, std::abs(direct));
    }
  // One FFT pair of a 24 x 18 array: round-off of a few 1e-16 relative to the largest value.
  EXPECT_LT(worst, 1e-12 * scale);
}

TEST(NonPeriodicHalfSpace, AUniformPatchIsLovesRectangle) {
  // Superposition of pixels is exact: a uniform pressure on a block of 5 x 3 pixels gives Love's formula for
  // the whole block, at every point of the grid.
  const Grid grid{.nx = 16, .ny = 10, .lx = 16e-6, .ly = 10e-6, .periodic = false};
  HeightMap p = HeightMap::Zero(grid.ny, grid.nx);
  const Real pressure = 3e8;
  p.block(4, 6, 3, 5).setConstant(pressure);  // rows 4..6, columns 6..10
  HeightMap u;
  make_nonperiodic_half_space(grid, testing::kPaperModulus)->apply(p, u);
  const Real centre_x = 8 * grid.dx(), centre_y = 5 * grid.dy();  // middle of the block's pixel centres
  for (Index iy = 0; iy < grid.ny; ++iy)
    for (Index ix = 0; ix < grid.nx; ++ix) {
      const Real expected = pressure / testing::kPaperModulus *
                            love_displacement(ix * grid.dx() - centre_x, iy * grid.dy() - centre_y,
                                              2.5 * grid.dx(), 1.5 * grid.dy());
      EXPECT_NEAR(u(iy, ix), expected, 1e-12 * expected) << ix << ", " << iy;  // round-off only
    }
}

TEST(PeriodicHalfSpace, SingleFourierModesAreScaledBy2OverEStarQ) {
  // Westergaard: p = p0 cos(q.x) gives u = 2 p0 cos(q.x)/(E* |q|) exactly on the lattice.
  const Grid grid{.nx = 32, .ny = 24, .lx = 32e-6, .ly = 30e-6, .periodic = true};
  const auto half_space = make_periodic_half_space(grid, testing::kPaperModulus);
  for (const auto& [kx, ky] : {std::pair<int, int>{3, 2}, {0, 5}, {16, 0}, {-4, 7}}) {
    const Real qx = 2 * pi * kx / grid.lx, qy = 2 * pi * ky / grid.ly, p0 = 1e8;
    HeightMap p(grid.ny, grid.nx);
    for (Index iy = 0; iy < grid.ny; ++iy)
      for (Index ix = 0; ix < grid.nx; ++ix)
        p(iy, ix) = p0 * std::cos(qx * ix * grid.dx() + qy * iy * grid.dy());
    HeightMap u;
    half_space->apply(p, u);
    const HeightMap expected = p * (2 / (testing::kPaperModulus * std::hypot(qx, qy)));
    // One FFT pair: round-off relative to the amplitude.
    EXPECT_LT((u - expected).abs().maxCoeff(), 1e-12 * expected.abs().maxCoeff()) << kx << ", " << ky;
  }
}

TEST(PeriodicHalfSpace, MeanPressureMovesNothing) {
  // The q = 0 mode is the solver's business (mean pressure, rigid-body approach): a uniform pressure gives
  // no displacement here.
  const Grid grid{.nx = 8, .ny = 8, .lx = 8e-6, .ly = 8e-6, .periodic = true};
  HeightMap u;
  make_periodic_half_space(grid, testing::kPaperModulus)->apply(HeightMap::Constant(8, 8, 1e8), u);
  EXPECT_LT(u.abs().maxCoeff(), 1e-25);
}

TEST(HalfSpace, IsSymmetricAndPositive) {
  // Reciprocity (Betti): <p1, G p2> = <p2, G p1>; energy: <p, G p> > 0 (for the periodic operator, for any
  // p with a non-zero fluctuating part). Consistency of one operator: 1e-12 relative.
  for (const bool periodic : {false, true}) {
    const Grid grid{.nx = 20, .ny = 14, .lx = 20e-6, .ly = 21e-6, .periodic = periodic};
    const auto half_space = make_half_space(grid, testing::kPaperModulus, 2);
    const HeightMap p1 = random_pressure(grid.nx, grid.ny, 2), p2 = random_pressure(grid.nx, grid.ny, 3);
    HeightMap u1, u2;
    half_space->apply(p1, u1);
    half_space->apply(p2, u2);
    const Real a = (p1 * u2).sum(), b = (p2 * u1).sum();
    EXPECT_NEAR(a, b, 1e-12 * std::abs(a)) << (periodic ? "periodic" : "non-periodic");
    // Energy of a signed pressure of zero mean (a positive pressure times a positive kernel is positive
    // whatever the kernel, so that check could not fail): <q, G q> > 0 and equal to an independent sum,
    // Parseval over a direct DFT (periodic: sum over modes of 2/(E*|q|) |Q|^2 / N) or the double sum of
    // Love's kernels (non-periodic). Tolerance 1e-10 relative: two summation orders of 280 x 280 terms with
    // cancellation (the energy is ~0.1 of sum |q||u|), measured below 1e-13. Rejects a modulus off by 1 %
    // or by 1/(1 - nu^2) (energy +10 %), and a kernel shifted by one node (energy 0.3 of the right one).
    const HeightMap q = p1 - p2;
    HeightMap uq;
    half_space->apply(q, uq);
    const Real energy = (q * uq).sum();
    Real expected = 0;
    const Real dx = grid.dx(), dy = grid.dy();
    if (periodic) {
      for (Index ky = 0; ky < grid.ny; ++ky)
        for (Index kx = 0; kx < grid.nx; ++kx) {
          if (kx == 0 && ky == 0) continue;
          std::complex<Real> mode = 0;
          for (Index iy = 0; iy < grid.ny; ++iy)
            for (Index ix = 0; ix < grid.nx; ++ix)
              mode +=
                  q(iy, ix) * std::polar(1.0, -2 * pi *
                                                  (static_cast<Real>(kx * ix) / static_cast<Real>(grid.nx) +
                                                   static_cast<Real>(ky * iy) / static_cast<Real>(grid.ny)));
          const Real sx = static_cast<Real>(kx <= grid.nx / 2 ? kx : kx - grid.nx);
          const Real sy = static_cast<Real>(ky <= grid.ny / 2 ? ky : ky - grid.ny);
          const Real wavenumber = 2 * pi * std::hypot(sx / grid.lx, sy / grid.ly);
          expected +=
              2 / (testing::kPaperModulus * wavenumber) * std::norm(mode) / static_cast<Real>(q.size());
        }
    } else {
      for (Index iy = 0; iy < grid.ny; ++iy)
        for (Index ix = 0; ix < grid.nx; ++ix)
          for (Index jy = 0; jy < grid.ny; ++jy)
            for (Index jx = 0; jx < grid.nx; ++jx)
              expected += q(iy, ix) * q(jy, jx) *
                          love_displacement((ix - jx) * dx, (iy - jy) * dy, dx / 2, dy / 2) /
                          testing::kPaperModulus;
    }
    EXPECT_GT(energy, 0) << (periodic ? "periodic" : "non-periodic");
    EXPECT_NEAR(energy, expected, 1e-10 * expected) << (periodic ? "periodic" : "non-periodic");
  }
}

TEST(HalfSpace, RefusesABadModulusAndAWrongShape) {
  const Grid grid{.nx = 4, .ny = 4, .lx = 4e-6, .ly = 4e-6, .periodic = false};
  EXPECT_THROW(make_half_space(grid, -1), Error);
  EXPECT_THROW(make_half_space(grid, std::nan("")), Error);
  HeightMap u;
  EXPECT_THROW(make_half_space(grid, testing::kPaperModulus)->apply(HeightMap::Zero(3, 4), u), Error);
}

}  // namespace
}  // namespace contactbench
