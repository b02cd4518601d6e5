// Greenwood-Williamson theory with Gaussian summit heights (Greenwood & Williamson, Proc. R. Soc. A 295,
// 1966; docs/theory.md section 5) and McCool's parameters from the profile moments (McCool, Wear 107, 1986,
// using Nayak's random-process results, Nayak, J. Lubr. Technol. 93, 1971).
//
// Summits of density eta, radius beta and Gaussian heights (mean ys above the mean plane of the surface,
// standard deviation sigma_s) each make an independent Hertz contact with the flat at separation d (measured
// from the same mean plane). With t = (d - ys)/sigma_s and F_n the Gaussian tail integrals:
//   N/A0 = eta F_0(t),  A/A0 = pi eta beta sigma_s F_1(t),  P/(E* A0) = (4/3) eta beta^(1/2) sigma_s^(3/2)
//   F_{3/2}(t).
// The theory ignores the interaction between summits, so A/A0 exceeds 1 at large loads; curves cap it at 1
// and say so.
#pragma once

#include <optional>
#include <span>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/isotropic_moments.hpp"

namespace contactbench {

struct GwParameters {
  Real eta = 0;      // summit density [1/m^2]
  Real beta = 0;     // summit radius of curvature [m]
  Real sigma_s = 0;  // standard deviation of the summit heights [m]
  Real ys = 0;       // mean summit height above the mean plane of the surface [m]
};

// Throws Error unless eta, beta, sigma_s are finite and > 0 and ys is finite.
void validate(const GwParameters& gw);

// The range of normalised separations t = (d - ys)/sigma_s in which curves are solved.
inline constexpr Real kGwMinSeparation = -10;
inline constexpr Real kGwMaxSeparation = 40;

// The separation d = ys + t sigma_s [m] of normalised separation t.
Real gw_separation(const GwParameters& gw, Real t);
// Contact spots per nominal area N/A0 = eta F_0(t) [1/m^2].
Real gw_spot_density(const GwParameters& gw, Real t);
// Real contact area A/A0 = pi eta beta sigma_s F_1(t), not capped at 1.
Real gw_area_fraction(const GwParameters& gw, Real t);
// Load P/(E* A0) = (4/3) eta beta^(1/2) sigma_s^(3/2) F_{3/2}(t) and its logarithm (finite where it
// underflows).
Real gw_load(const GwParameters& gw, Real t);
Real gw_log_load(const GwParameters& gw, Real t);
// The contact stiffness K/E* = -d(P/(E* A0))/dd = 2 eta beta^(1/2) sigma_s^(1/2) F_{1/2}(t) [1/m]
// (dF_{3/2}/dt = -(3/2) F_{1/2}; docs/theory.md section 12.4).
Real gw_stiffness(const GwParameters& gw, Real t);

// McCool's parameters (Wear 107, 1986) from isotropic profile moments m0, m2, m4 and alpha = m0 m4/m2^2:
//   eta = m4/(6 pi sqrt3 m2),  beta = (3/8) sqrt(pi/m4),  sigma_s^2 = (1 - 0.8968/alpha) m0,  ys = 4
//   m2/sqrt(pi m4).
// Refuses alpha <= 0.8968 (sigma_s^2 would be <= 0).
GwParameters mccool_parameters(const IsotropicMoments& moments);
// The same from a surface's moments: m2, m4 are the means of x and y; refuses anisotropy above 5 %
// (isotropic_moments).
GwParameters mccool_parameters(const SpectralMoments& moments);

// The normalised separation t in [kGwMinSeparation, kGwMaxSeparation] at which the load is `load` (P/(E*
// A0)), solved with Brent's method on ln P to 1e-13 in ln P. Throws Error naming the load and the largest
// (smallest) load reachable when it lies beyond the range.
Real gw_solve_separation(const GwParameters& gw, Real load);

// The load-area curve at the requested loads (finite, > 0, ascending), each solved for its separation.
// load: the model's load at the solved separation (equal to the request to 1e-12); area_fraction: capped at
// 1, and the parameters then say "capped at A/A0 = 1 for loads >= X" with X the load at which GW's A/A0
// reaches 1; separation: d = ys + t sigma_s [m]; spots: N/A0 times nominal_area [m^2] when given, NaN
// otherwise. method "greenwood_williamson"; parameters list eta, beta, sigma_s, ys.
LoadAreaCurve greenwood_williamson_curve(const GwParameters& gw, std::span<const Real> loads,
                                         std::optional<Real> nominal_area = std::nullopt);

// GW with McCool's parameters from the surface's moments (method "gw_mccool"); the parameters string also
// states the moments used (profile moments, means of x and y).
LoadAreaCurve gw_mccool_curve(const SpectralMoments& moments, std::span<const Real> loads,
                              std::optional<Real> nominal_area = std::nullopt);

}  // namespace contactbench
