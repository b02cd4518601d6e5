// Exact solutions of frictionless elastic contact that judge the solvers (docs/theory.md section 6), kept
// apart from them and tested on their own first (tests/test_reference_solutions.cpp), as ContactMechanics
// keeps its ReferenceSolutions. E* is the contact modulus [Pa]; loads are forces [N] for the axisymmetric
// contacts and mean pressures [Pa] for the periodic ones.
#pragma once

#include "contactbench/core/types.hpp"

namespace contactbench::reference {

// A rigid sphere of radius R on an elastic half-space (H. Hertz 1882; K. L. Johnson, Contact Mechanics,
// 1985, section 4.2, eqs. 4.22-4.23).
struct HertzSphere {
  Real radius = 0;   // R [m]
  Real modulus = 0;  // E* [Pa]

  Real contact_radius(Real load) const;       // a = (3 P R/(4 E*))^(1/3) [m]
  Real load_of_contact_radius(Real a) const;  // P = 4 E* a^3/(3 R) [N]
  Real peak_pressure(Real load) const;        // p0 = 3 P/(2 pi a^2) [Pa]
  Real approach(Real load) const;             // delta = a^2/R [m]
  Real load_of_approach(Real delta) const;    // P = (4/3) E* R^(1/2) delta^(3/2) [N]
  Real pressure(Real r, Real load) const;     // p0 sqrt(1 - r^2/a^2) inside, 0 outside [Pa]
};

// A rigid flat-ended cylinder of radius a pressed into a half-space (J. Boussinesq 1885; I. N. Sneddon,
// Int. J. Eng. Sci. 3, 47, 1965; Johnson 1985, eq. 3.34).
struct FlatPunch {
  Real radius = 0;   // a [m]
  Real modulus = 0;  // E* [Pa]

  Real stiffness() const;                  // dP/d(delta) = 2 E* a [N/m]
  Real pressure(Real r, Real load) const;  // P/(2 pi a sqrt(a^2 - r^2)) for r < a, 0 outside [Pa]
};

// Westergaard's wavy surface h = D cos(2 pi x/lambda) (H. M. Westergaard, J. Appl. Mech. 6, 1939; Johnson
// 1985, section 13.2): contact in strips of half-width a, sin^2(pi a/lambda) = pbar/p*, under the mean
// pressure pbar; full contact from p* = pi E* D/lambda on.
struct WavySurface {
  Real amplitude = 0;   // D [m]
  Real wavelength = 0;  // lambda [m]
  Real modulus = 0;     // E* [Pa]

  Real full_contact_pressure() const;        // p* [Pa]
  Real contact_half_width(Real pbar) const;  // a [m]; lambda/2 from p* on
  Real pressure(Real x, Real pbar) const;  // at x from a crest [Pa]; pbar + p* cos(2 pi x/lambda) from p* on
};

// The bi-sinusoid h = D cos(2 pi x/lambda) cos(2 pi y/lambda) (K. L. Johnson, J. A. Greenwood, J. G.
// Higginson, Int. J. Mech. Sci. 27, 383, 1985): full contact from p* = sqrt2 pi E* D/lambda on, and the two
// asymptotes of its contact area.
struct Bisinusoid {
  Real amplitude = 0;   // D [m]
  Real wavelength = 0;  // lambda [m]
  Real modulus = 0;     // E* [Pa]

  Real full_contact_pressure() const;  // p* [Pa]
  // Small loads: two Hertz contacts a cell (the crests, radius of curvature lambda^2/(4 pi^2 D)):
  // A/A0 ~ pi (3/(8 pi))^(2/3) (pbar/p*)^(2/3).
  static Real small_load_area_fraction(Real load_ratio);
  // Near full contact: two shrinking non-contact islands at the saddles: 1 - A/A0 ~ (3/(2 pi)) (1 - pbar/p*).
  static Real near_full_gap_fraction(Real load_ratio);
};

}  // namespace contactbench::reference
