// The full Bush-Gibson-Thomas model (A. W. Bush, R. D. Gibson and T. R. Thomas, Wear 35, 87, 1975;
// docs/theory.md section 5): the summits of an isotropic Gaussian surface are elliptic paraboloids with
// Nayak's joint distribution of height and principal curvatures (P. R. Nayak, J. Lubr. Technol. 93, 398,
// 1971), each an independent elliptic Hertz contact with the rigid flat (K. L. Johnson, Contact Mechanics,
// 1985, sec. 4.2).
//
// Summit density (docs/theory.md section 5, Kac-Rice form): n(z, H) = (2 pi m2)^-1 g(z, H) |det H| [H neg.
// def.]. With u = (hxx + hyy)/2 ~ N(0, 2 m4/3), v = (hxx - hyy)/2, w = hxy ~ N(0, m4/3), all independent, the
// principal curvatures of a summit are kbar -+ r with kbar = -u > r = sqrt(v^2 + w^2) >= 0, and its height
// is N(mu, s^2) given kbar, mu = (3 m2/(2 m4)) kbar, s^2 = m0 (1 - 3/(2 alpha)), alpha = m0 m4/m2^2.
// Per unit area, with N(kbar; 0, 2 m4/3) the normal density,
//   w(kbar, r) = (2 pi m2)^-1 (kbar^2 - r^2) N(kbar; 0, 2 m4/3) (2 pi m4/3)^-1 exp(-3 r^2/(2 m4)) 2 pi r.
// The factor is 2 pi r (from dv dw = r dr dphi), not 4 pi r: the Jacobian 2 of (hxx, hyy, hxy) -> (u, v, w)
// is already in the density of (u, v, w), g = p(u, v, w)/2; counting it again doubles Nayak's summit
// density m4/(6 pi sqrt3 m2) (tested).
// A summit at interference delta = z - d > 0 makes a contact of area c_A delta and load c_P delta^(3/2) E*
// (elliptic Hertz), so with t = (d - mu)/s and F_n the Gaussian tail integrals (gaussian_tail_integrals.hpp):
//   N/A0 = int w F_0(t),   A/A0 = int w c_A s F_1(t),   P/(E* A0) = int w c_P s^(3/2) F_{3/2}(t).
//
// Quadrature (all d-independent work is done once per surface). With x = kbar/sqrt(m4), rho = r/kbar < 1:
//   w dkbar dr = C (m4/m2) x^4 exp(-3 x^2/4) rho (1 - rho^2) exp(-3 x^2 rho^2/2) drho dx,
//   C = 3 sqrt3/(4 pi^1.5),
// and c_A kbar, c_P kbar^(1/2) depend on rho alone (the curvature ratio). The rho integral, for each x node,
// runs in u = rho^2 with tanh-sinh nodes (the integrand behaves like (1 - u)^(1/2)/ln(1/(1 - u)) at u -> 1,
// where kappa1 -> 0, and like exp(-3 x^2 u/2) at u -> 0); the x integral uses the trapezoidal rule in
// v = sqrt(x) (the integrand is then smooth and vanishes with its low derivatives at v = 0) on [0, v_max],
// v_max chosen so that the summits that matter at the largest separation are covered. A load at any
// separation is then a one-dimensional sum over the x nodes of (precomputed weight) F_n(t), in logarithms.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "contactbench/core/load_area_curve.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/theories/isotropic_moments.hpp"

namespace contactbench {

// Elliptic Hertz contact of the paraboloid z = z_s - (kappa1 x^2 + kappa2 y^2)/2 pressed onto a rigid flat at
// interference delta (Johnson 1985, eqs. 4.39, with A = kappa1/2 <= B = kappa2/2):
//   contact area = area_coefficient * delta,   P/E* = load_coefficient * delta^(3/2),
// axis_ratio = b/a <= 1 of the contact ellipse (independent of the load).
struct EllipticHertz {
  Real area_coefficient = 0;  // c_A [m]: pi R for a sphere of radius R
  Real load_coefficient = 0;  // c_P [m^(1/2)]: (4/3) R^(1/2) for a sphere
  Real axis_ratio = 1;        // b/a
};

// 0 < kappa1 <= kappa2, both finite [1/m]; throws Error otherwise.
EllipticHertz elliptic_hertz(Real kappa1, Real kappa2);

// Quadrature resolution: level 0 is the default; each level halves both steps (doubles the node counts).
struct BgtQuadrature {
  int level = 0;
};

// The normalised separations zeta = d/sqrt(m0) in which curves are solved.
inline constexpr Real kBgtMinSeparation = -5;
inline constexpr Real kBgtMaxSeparation = 30;

class BushGibsonThomas {
 public:
  // Refuses (Error) non-positive or non-finite moments and alpha = m0 m4/m2^2 <= 1.5 (then s^2 <= 0: a
  // degenerate, non-Gaussian summit height distribution). Builds the quadrature once (about 1 ms): 129 nodes
  // in rho, and in x a number that grows like (alpha - 1.5)^(-1/2) as alpha -> 1.5 (98 at alpha = 92, 459 at
  // alpha = 2, 992 at alpha = 1.6), since the summits at one separation then have nearly one curvature.
  explicit BushGibsonThomas(const IsotropicMoments& moments, BgtQuadrature quadrature = {});

  const IsotropicMoments& moments() const { return moments_; }
  Real alpha() const { return alpha_; }
  Index curvature_nodes() const { return curvature_nodes_; }  // nodes in x = kbar/sqrt(m4)
  Index shape_nodes() const { return shape_nodes_; }          // nodes in rho = r/kbar

  // Summit density per unit area int w [1/m^2] and mean summit height int w mu / int w [m], both by the
  // model's quadrature (Nayak: m4/(6 pi sqrt3 m2) and 4 m2/sqrt(pi m4)).
  Real summit_density() const;
  Real mean_summit_height() const;

  // At separation d [m] of the flat from the mean plane: contact spots per unit area N/A0 [1/m^2], A/A0 (not
  // capped at 1), P/(E* A0) and its logarithm (finite where the load underflows).
  Real spot_density(Real d) const;
  Real area_fraction(Real d) const;
  Real log_area_fraction(Real d) const;
  Real load(Real d) const;
  Real log_load(Real d) const;
  // The contact stiffness K/E* = -d(P/(E* A0))/dd [1/m] at separation d: with dF_{3/2}/dt = -(3/2) F_{1/2},
  // int w c_P (3/2) s^(1/2) F_{1/2}(t) (docs/theory.md section 12.4).
  Real stiffness(Real d) const;

  // The separation d [m] in [kBgtMinSeparation, kBgtMaxSeparation] sqrt(m0) at which P/(E* A0) = load, solved
  // with Brent's method on ln P to 1e-13. Throws Error naming the load and the reachable limit beyond range.
  Real solve_separation(Real load) const;

 private:
  // ln sum_i exp(log_weight[i] + ln F_n(t_i)), t_i = (d - mu_i)/s.
  Real log_sum(const std::vector<Real>& log_weight, Real n, Real d) const;

  IsotropicMoments moments_;
  Real alpha_ = 0;
  Real s_ = 0;  // standard deviation of the summit heights given the curvature [m]
  Index curvature_nodes_ = 0, shape_nodes_ = 0;
  std::vector<Real> mu_;  // mean height of the summits at each x node [m]
  std::vector<Real> log_spot_weight_, log_area_weight_, log_load_weight_;
};

// The full BGT load-area curve at the requested loads P/(E* A0) (finite, > 0, ascending): method "bgt";
// load: the model's load at the solved separation (equal to the request to 1e-12); area_fraction: capped at 1
// (the parameters then say from which load); separation: d [m]; spots: N/A0 times nominal_area [m^2] when
// given, NaN otherwise. Refuses anisotropy above 5 % (isotropic_moments) and alpha <= 1.5.
LoadAreaCurve bgt_curve(const SpectralMoments& moments, std::span<const Real> loads,
                        std::optional<Real> nominal_area = std::nullopt);

}  // namespace contactbench
