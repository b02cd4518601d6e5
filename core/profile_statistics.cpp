#include "contactbench/core/profile_statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contactbench/core/error.hpp"

namespace contactbench {

ProfileStatistics profile_statistics(std::span<const Real> x, std::span<const Real> h) {
  if (x.size() != h.size() || x.size() < 3) throw Error("a profile needs at least three points");
  const std::size_t n = x.size();
  ProfileStatistics s;
  s.points = static_cast<Index>(n);
  s.length = x[n - 1] - x[0];
  // The piecewise-linear profile: on a segment of width d from h0 to h1, integral h = d (h0 + h1) / 2 and
  // integral h^2 = d (h0^2 + h0 h1 + h1^2) / 3. The mean is removed from the samples first, so that the
  // variance is not a small difference of large squares.
  Real plain_mean = 0;
  for (const Real v : h)
    plain_mean += v;
  plain_mean /= static_cast<Real>(n);
  Real integral = 0, squares = 0, slopes = 0, point_squares = 0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    const Real d = x[k + 1] - x[k];
    if (!(d > 0)) throw Error("a profile's x must increase strictly");
    const Real a = h[k] - plain_mean, b = h[k + 1] - plain_mean;
    integral += d * (a + b) / 2;
    squares += d * (a * a + a * b + b * b) / 3;
    slopes += (b - a) * (b - a) / d;
  }
  for (const Real v : h)
    point_squares += (v - plain_mean) * (v - plain_mean);
  const Real offset = integral / s.length;
  s.mean = plain_mean + offset;
  s.rq = std::sqrt(std::max(Real{0}, squares / s.length - offset * offset));
  s.rq_points = std::sqrt(point_squares / static_cast<Real>(n));
  s.rms_slope = std::sqrt(slopes / s.length);
  const Real step = s.length / static_cast<Real>(n - 1);
  s.uniform = true;
  for (std::size_t k = 0; k + 1 < n; ++k)
    s.uniform = s.uniform && std::abs(x[k + 1] - x[k] - step) <= 1e-3 * step;
  if (s.uniform) {
    Real curvatures = 0;
    for (std::size_t k = 1; k + 1 < n; ++k) {
      const Real c = (h[k + 1] - 2 * h[k] + h[k - 1]) / (step * step);
      curvatures += c * c;
    }
    s.rms_curvature = std::sqrt(curvatures / static_cast<Real>(n - 2));
  }
  return s;
}

SpectralMoments isotropic_moments(const ProfileStatistics& profile) {
  const Real m4 = profile.rms_curvature ? *profile.rms_curvature * *profile.rms_curvature
                                        : std::numeric_limits<Real>::quiet_NaN();
  return {.m0 = profile.m0(), .m2x = profile.m2(), .m4x = m4, .m2y = profile.m2(), .m4y = m4};
}

}  // namespace contactbench
