// Persson's theory beyond the area (docs/theory.md section 12.3): the mean gap u-bar(p) (B. N. J. Persson,
// Phys. Rev. Lett. 99, 125502, 2007; C. Yang and B. N. J. Persson, J. Phys.: Condens. Matter 20, 215214,
// 2008), its contact stiffness K = -dp/du-bar, and the pressure distribution P(sigma) of the diffusion
// equation in the magnification (Persson, J. Chem. Phys. 115, 3840, 2001).
//
// With w(q) = (pi int_q0^q q'^3 C(q') dq')^(-1/2) and P(q, p) = erf(p w(q)/E*) the area seen at
// magnification q,
//   u-bar(p) = sqrt(pi) int_q0^q1 dq q^2 C(q) w(q) int_p^inf dp'/p' [gamma + 3 (1 - gamma) P^2(q, p')]
//              exp(-(w(q) p'/E*)^2),
// and, differentiating under the integral,
//   1/K = -du-bar/dp = sqrt(pi) int dq q^2 C(q) w(q) (1/p) [gamma + 3 (1 - gamma) P^2(q, p)]
//                      exp(-(w(q) p/E*)^2).
// The inner integral is a function of s0 = w(q) p/E* alone, tabulated once. The q integral runs over the
// surface's own lattice spectrum (the isotropic identity int d^2q = 2 pi int q dq applied to the lattice sum,
// as persson_q3_integral does), so no radial average is made.
#pragma once

#include <span>
#include <vector>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// Persson's empirical factor for the gap outside the contact (Persson 2007 and Yang-Persson 2008 take it
// between 0.4 and 0.5); 0.45 here, stated in the method's parameters.
inline constexpr Real kPerssonGapGamma = 0.45;

class PerssonGap {
 public:
  // From the surface's Fourier coefficients (every mode but q = 0); gamma in [0, 1]. Throws Error on a
  // surface without roughness.
  explicit PerssonGap(const FourierCoefficients& coefficients, Real gamma = kPerssonGapGamma);

  // At load = p/E* > 0: the mean gap [m] and the stiffness K/E* = -d(p/E*)/du-bar [1/m].
  Real mean_gap(Real load) const;
  Real stiffness(Real load) const;

  Real gamma() const { return gamma_; }

 private:
  Real gamma_;
  std::vector<Real> weight_;  // per mode, in increasing |q|: (1/(2 pi)) |q| C(q) dqx dqy  [m]
  std::vector<Real> w_;       // per mode: w(|q|), the q^3 integral up to and including the mode
};

// Persson's pressure distribution at full magnification for the nominal pressure load = p/E* (docs/theory.md
// 11.3): the density of sigma/E* on sigma > 0,
//   P(s) = (4 pi g)^(-1/2) [exp(-(s - load)^2/(4 g)) - exp(-(s + load)^2/(4 g))],   g = G/E*^2 =
//   (pi/4) q3_integral,
// whose integral over s > 0 is the area fraction erf(load/(2 sqrt(g))) (the non-contact rest is a delta at 0)
// and whose first moment is the load.
Real persson_pressure_density(Real sigma_over_estar, Real load, Real q3_integral);

}  // namespace contactbench
