// Statistics of a one-dimensional profile h(x) sampled at increasing, possibly uneven x: what a line scan
// gives without assuming anything across the line (docs/formats.md "line scans", docs/theory.md section 1).
#pragma once

#include <optional>
#include <span>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct ProfileStatistics {
  Index points = 0;
  Real length = 0;                    // x_last - x_first [m]
  Real mean = 0;                      // of the piecewise-linear profile, (1/L) integral of h dx
  Real rq = 0;                        // rms about that mean of the piecewise-linear profile [m]
  Real rq_points = 0;                 // rms of the samples about their plain mean [m]
  Real rms_slope = 0;                 // sqrt((1/L) integral of h'^2 dx), h' constant on each segment
  std::optional<Real> rms_curvature;  // from second differences, only when the sampling is uniform
  bool uniform = false;               // every step within 1e-3 of the mean step
  // Nayak's profile moments: m0 = rq^2, m2 = rms_slope^2, m4 = rms_curvature^2; alpha = m0 m4 / m2^2.
  Real m0() const { return rq * rq; }
  Real m2() const { return rms_slope * rms_slope; }
};

// Throws Error for fewer than three points or x not strictly increasing.
ProfileStatistics profile_statistics(std::span<const Real> x, std::span<const Real> h);

// The moments of the isotropic surface whose every profile has these statistics (docs/theory.md section 1:
// for an isotropic surface the profile moments are the same in every direction): m0, and m2 and m4 the same
// along x and y. m4 is NaN when the sampling is not uniform (no curvature): the theories that read it refuse.
SpectralMoments isotropic_moments(const ProfileStatistics& profile);

}  // namespace contactbench
