// Profile statistics of a line scan (core/profile_statistics.hpp) against profiles whose integrals are known
// in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/profile_statistics.hpp"

namespace contactbench {
namespace {

TEST(ProfileStatistics, ALineIsIntegratedExactlyHoweverItIsSampled) {
  // h = 3 x + 1 on [0, 2]: the piecewise-linear profile is the line itself, at any sampling, so
  // rq = 3 L / sqrt(12) = sqrt(3), slope 3, mean 4, curvature 0. Uneven points and even points agree; the
  // tolerance, 1e-14 relative, is a few roundings of sums over at most six segments.
  const std::vector<double> uneven = {0, 0.1, 0.5, 0.6, 1.7, 2};
  const std::vector<double> even = {0, 0.5, 1, 1.5, 2};
  for (const auto* x : {&uneven, &even}) {
    std::vector<double> h;
    for (const double v : *x)
      h.push_back(3 * v + 1);
    const ProfileStatistics s = profile_statistics(*x, h);
    EXPECT_NEAR(s.length, 2, 1e-15);
    EXPECT_NEAR(s.mean, 4, 1e-14 * 4);
    EXPECT_NEAR(s.rq, std::sqrt(3.0), 1e-14 * std::sqrt(3.0));
    EXPECT_NEAR(s.rms_slope, 3, 1e-14 * 3);
    EXPECT_EQ(s.uniform, x == &even);
    if (x == &even) {
      ASSERT_TRUE(s.rms_curvature.has_value());
      EXPECT_NEAR(*s.rms_curvature, 0, 1e-12);
    } else {
      EXPECT_FALSE(s.rms_curvature.has_value());
    }
  }
}

TEST(ProfileStatistics, ASampledSineApproachesItsContinuousMoments) {
  // h = A sin(k x) over whole periods: rq = A / sqrt(2), rms slope = A k / sqrt(2), rms curvature = A k^2 /
  // sqrt(2). Linear interpolation between 4096 points a period changes them by O((k dx)^2) = 2.4e-6 relative.
  const double amplitude = 2e-6, k = 2 * M_PI / 1e-4;
  const int n = 3 * 4096 + 1;
  std::vector<double> x(n), h(n);
  for (int i = 0; i < n; ++i) {
    x[i] = 3e-4 * i / (n - 1);
    h[i] = amplitude * std::sin(k * x[i]);
  }
  const ProfileStatistics s = profile_statistics(x, h);
  EXPECT_NEAR(s.rq, amplitude / std::sqrt(2.0), 1e-5 * amplitude);
  EXPECT_NEAR(s.rms_slope, amplitude * k / std::sqrt(2.0), 1e-5 * amplitude * k);
  ASSERT_TRUE(s.rms_curvature.has_value());
  // The curvature is a mean over the n - 2 inner points (second differences), whose sin^2 average
  // (n - 1) / (2 (n - 2)) exceeds 1/2 by 1 / (2 (n - 2)): 4.1e-5 relative in the rms, hence 6e-5.
  EXPECT_NEAR(*s.rms_curvature, amplitude * k * k / std::sqrt(2.0), 6e-5 * amplitude * k * k);
}

TEST(ProfileStatistics, TooFewPointsOrXNotIncreasingAreRefused) {
  EXPECT_THROW(profile_statistics(std::vector<double>{0, 1}, std::vector<double>{0, 1}), Error);
  EXPECT_THROW(profile_statistics(std::vector<double>{0, 1, 1}, std::vector<double>{0, 1, 2}), Error);
}

}  // namespace
}  // namespace contactbench
