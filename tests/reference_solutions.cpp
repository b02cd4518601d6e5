#include "reference_solutions.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace contactbench::reference {

namespace {}

Real HertzSphere::contact_radius(Real load) const {
  return std::cbrt(3 * load * radius / (4 * modulus));
}
Real HertzSphere::load_of_contact_radius(Real a) const {
  return 4 * modulus * a * a * a / (3 * radius);
}
Real HertzSphere::peak_pressure(Real load) const {
  const Real a = contact_radius(load);
  return 3 * load / (2 * pi * a * a);
}
Real HertzSphere::approach(Real load) const {
  const Real a = contact_radius(load);
  return a * a / radius;
}
Real HertzSphere::load_of_approach(Real delta) const {
  return 4.0 / 3.0 * modulus * std::sqrt(radius) * std::pow(delta, 1.5);
}
Real HertzSphere::pressure(Real r, Real load) const {
  const Real a = contact_radius(load);
  return r < a ? peak_pressure(load) * std::sqrt(1 - r * r / (a * a)) : 0;
}

Real FlatPunch::stiffness() const {
  return 2 * modulus * radius;
}
Real FlatPunch::pressure(Real r, Real load) const {
  return r < radius ? load / (2 * pi * radius * std::sqrt(radius * radius - r * r)) : 0;
}

Real WavySurface::full_contact_pressure() const {
  return pi * modulus * amplitude / wavelength;
}
Real WavySurface::contact_half_width(Real pbar) const {
  const Real ratio = std::min<Real>(pbar / full_contact_pressure(), 1);
  return wavelength * std::asin(std::sqrt(ratio)) / pi;
}
Real WavySurface::pressure(Real x, Real pbar) const {
  const Real p_star = full_contact_pressure();
  if (pbar >= p_star) return pbar + p_star * std::cos(2 * pi * x / wavelength);
  const Real s2 = pbar / p_star;  // sin^2(pi a/lambda)
  const Real sx2 = std::pow(std::sin(pi * x / wavelength), 2);
  if (sx2 >= s2) return 0;
  return 2 * pbar * std::abs(std::cos(pi * x / wavelength)) / s2 * std::sqrt(s2 - sx2);
}

Real Bisinusoid::full_contact_pressure() const {
  return std::sqrt(2.0) * pi * modulus * amplitude / wavelength;
}
Real Bisinusoid::small_load_area_fraction(Real load_ratio) {
  return pi * std::pow(3 / (8 * pi), 2.0 / 3) * std::pow(load_ratio, 2.0 / 3);
}
Real Bisinusoid::near_full_gap_fraction(Real load_ratio) {
  return 3 / (2 * pi) * (1 - load_ratio);
}

}  // namespace contactbench::reference
