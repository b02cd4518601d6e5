// The Fourier filter of the preconditioned solvers (bem/fourier_preconditioner.hpp): (E*/2)|q| on single
// modes, and its unit form (peak 1), which active_set runs in single precision whatever the units.
#include "contactbench/bem/fourier_preconditioner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace contactbench {
namespace {

constexpr Real kModulus = 1e11;

std::vector<double> random_field(const Grid& grid, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<double> field(static_cast<std::size_t>(grid.points()));
  for (double& v : field)
    v = uniform(random);
  return field;
}

TEST(FourierPreconditioner, ASingleModeIsScaledByHalfEStarQ) {
  // r = cos(q.x) on a periodic lattice gives z = (E*/2)|q| cos(q.x): one FFT pair, round-off only.
  const Grid grid{.nx = 32, .ny = 24, .lx = 32e-6, .ly = 30e-6, .periodic = true};
  const auto filter = make_fourier_preconditioner<double>(grid, kModulus);
  for (const auto& [kx, ky] : {std::pair<int, int>{3, 2}, {0, 5}, {16, 0}, {-4, 7}}) {
    const Real qx = 2 * std::numbers::pi * kx / grid.lx, qy = 2 * std::numbers::pi * ky / grid.ly;
    std::vector<double> r(static_cast<std::size_t>(grid.points())), z(r.size());
    for (Index iy = 0; iy < grid.ny; ++iy)
      for (Index ix = 0; ix < grid.nx; ++ix)
        r[static_cast<std::size_t>(iy * grid.nx + ix)] = std::cos(qx * ix * grid.dx() + qy * iy * grid.dy());
    filter->apply(r.data(), z.data());
    const double scale = kModulus / 2 * std::hypot(qx, qy);
    for (std::size_t k = 0; k < r.size(); ++k)
      EXPECT_NEAR(z[k], scale * r[k], 1e-12 * scale) << kx << ", " << ky << " at " << k;
  }
}

TEST(FourierPreconditioner, TheUnitFilterIsThePhysicalOneOverItsPeak) {
  // The same filter divided by (E*/2) max|q|, max|q| = pi sqrt(1/dx^2 + 1/dy^2) on an even lattice (the
  // corner of the Nyquist box), periodic and zero-padded: equal to round-off (1e-12 relative).
  for (const bool periodic : {true, false}) {
    const Grid grid{.nx = 16, .ny = 12, .lx = 16e-6, .ly = 18e-6, .periodic = periodic};
    const auto physical = make_fourier_preconditioner<double>(grid, kModulus);
    const auto unit = make_unit_fourier_preconditioner<double>(grid);
    const std::vector<double> r = random_field(grid, 3);
    std::vector<double> z_physical(r.size()), z_unit(r.size());
    physical->apply(r.data(), z_physical.data());
    unit->apply(r.data(), z_unit.data());
    const double peak = kModulus / 2 * std::numbers::pi * std::hypot(1 / grid.dx(), 1 / grid.dy());
    double largest = 0;
    for (const double v : z_physical)
      largest = std::max(largest, std::abs(v));
    for (std::size_t k = 0; k < r.size(); ++k)
      EXPECT_NEAR(z_unit[k] * peak, z_physical[k], 1e-12 * largest) << (periodic ? "periodic" : "padded");
  }
}

TEST(FourierPreconditioner, TheUnitFilterKeepsFloatsRangeWhateverTheUnits) {
  // Pixels of 1e-95 m put |q| near 1e95, beyond float's range (3.4e38): the physical filter in float can
  // only overflow, the unit one gives the double precision unit filter to float's accuracy (1e-5 of the
  // largest value: a few roundings of 6e-8 in each of the transforms' sums).
  const Grid grid{.nx = 16, .ny = 16, .lx = 16e-95, .ly = 16e-95, .periodic = true};
  const auto unit_float = make_unit_fourier_preconditioner<float>(grid);
  const auto unit_double = make_unit_fourier_preconditioner<double>(grid);
  const std::vector<double> r = random_field(grid, 4);
  std::vector<float> r_float(r.begin(), r.end()), z_float(r.size());
  std::vector<double> z_double(r.size());
  unit_float->apply(r_float.data(), z_float.data());
  unit_double->apply(r.data(), z_double.data());
  double largest = 0;
  for (const double v : z_double)
    largest = std::max(largest, std::abs(v));
  ASSERT_GT(largest, 0.1);  // a filter of peak 1 on values of order 1
  for (std::size_t k = 0; k < r.size(); ++k) {
    ASSERT_TRUE(std::isfinite(z_float[k])) << k;
    EXPECT_NEAR(z_float[k], z_double[k], 1e-5 * largest) << k;
  }
}

}  // namespace
}  // namespace contactbench
