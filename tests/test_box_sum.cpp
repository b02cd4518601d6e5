// The window sums of bem/box_sum.hpp against the sum of every window point by point.
#include "contactbench/bem/box_sum.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace contactbench {
namespace {

// The sum over the (2 radius + 1)^2 window at (x, y), point by point: wrapped when periodic, the points
// outside the grid left out otherwise.
double direct_sum(const std::vector<double>& v, Index nx, Index ny, Index radius, bool periodic, Index x,
                  Index y) {
  double sum = 0;
  for (Index dy = -radius; dy <= radius; ++dy)
    for (Index dx = -radius; dx <= radius; ++dx) {
      Index i = x + dx, j = y + dy;
      if (periodic) {
        i = (i + nx) % nx;
        j = (j + ny) % ny;
      } else if (i < 0 || i >= nx || j < 0 || j >= ny) {
        continue;
      }
      sum += v[static_cast<std::size_t>(j * nx + i)];
    }
  return sum;
}

TEST(BoxSum, MatchesTheSumOfEveryWindow) {
  // A non-square grid with odd sides, radii from 0 to the largest a periodic window allows, 1 to 4 threads
  // (rows split differently; with 4, blocks of 2 or 3 rows, shorter than most windows). Running sums add and
  // subtract: agreement to 1e-12 of the values' scale (each sum is of at most 9 x 9 = 81 values of order 1, a
  // few hundred roundings of 1e-16).
  const Index nx = 11, ny = 9;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<double> values(static_cast<std::size_t>(nx * ny));
  for (double& v : values)
    v = uniform(random);
  std::vector<WindowRows> scratch;
  std::vector<double> sums(values.size());
  for (const bool periodic : {true, false})
    for (const Index radius : {0, 1, 2, 4})
      for (const int threads : {1, 2, 3, 4}) {
        box_sum(
            nx, ny, radius, periodic,
            [&](Index y, double* row) { std::copy_n(values.begin() + y * nx, nx, row); },
            [&](Index y, const double* row, int) { std::copy_n(row, nx, sums.begin() + y * nx); }, scratch,
            threads);
        for (Index y = 0; y < ny; ++y)
          for (Index x = 0; x < nx; ++x)
            EXPECT_NEAR(sums[static_cast<std::size_t>(y * nx + x)],
                        direct_sum(values, nx, ny, radius, periodic, x, y), 1e-12)
                << (periodic ? "periodic" : "non-periodic") << ", radius " << radius << ", " << threads
                << " threads, at (" << x << ", " << y << ")";
      }
}

TEST(BoxSum, RowsAskedInAnyOrderHaveTheirWindowSums) {
  // A convolution's producer asks a thread's rows in order, chunk after chunk, and starts again at the
  // next apply: rows in sequence, jumps forward and back, the same row twice, and a restart after the
  // inputs changed. Tolerance as above.
  const Index nx = 13, ny = 10, radius = 3;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<double> values(static_cast<std::size_t>(nx * ny));
  for (double& v : values)
    v = uniform(random);
  auto value_row = [&](Index y, double* row) { std::copy_n(values.begin() + y * nx, nx, row); };
  for (const bool periodic : {true, false}) {
    WindowRows window(nx, ny, radius, periodic);
    for (int pass = 0; pass < 2; ++pass) {
      for (const Index y : {2, 3, 4, 5, 9, 0, 1, 1, 7, 8, 9}) {
        const double* sums = window.sums(y, value_row);
        for (Index x = 0; x < nx; ++x)
          EXPECT_NEAR(sums[x], direct_sum(values, nx, ny, radius, periodic, x, y), 1e-12)
              << (periodic ? "periodic" : "non-periodic") << ", pass " << pass << ", at (" << x << ", " << y
              << ")";
      }
      for (double& v : values)  // new inputs: the window must not reuse the old rows
        v = uniform(random);
      window.restart();
    }
  }
}

TEST(BoxSum, EmitsEveryRowOnceFromAThreadOfTheTeam) {
  const Index nx = 16, ny = 13;
  std::vector<int> visits(static_cast<std::size_t>(nx * ny), 0);
  std::vector<WindowRows> scratch;
  box_sum(
      nx, ny, 3, false, [&](Index, double* row) { std::fill_n(row, nx, 1.0); },
      [&](Index y, const double*, int thread) {
        EXPECT_GE(thread, 0);
        EXPECT_LT(thread, 2);
        for (Index x = 0; x < nx; ++x) {
#pragma omp atomic
          ++visits[static_cast<std::size_t>(y * nx + x)];
        }
      },
      scratch, 2);
  for (const int v : visits)
    EXPECT_EQ(v, 1);
}

}  // namespace
}  // namespace contactbench
