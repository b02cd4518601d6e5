#include "contactbench/theories/pastewka_robbins_criterion.hpp"

#include <cmath>
#include <string>

#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

PastewkaRobbinsCriterion pastewka_robbins_criterion(const SpectralMoments& moments, Real estar,
                                                    const AdhesionLaw& law) {
  validate_adhesion_law(law, "Pastewka-Robbins criterion");
  const IsotropicMoments m = isotropic_moments(moments, "Pastewka-Robbins criterion");
  PastewkaRobbinsCriterion c;
  c.rms_gradient = std::sqrt(moments.m2x + moments.m2y);
  // <(h_xx + h_yy)²> = 2 m4 + 2 <h_xx h_yy> = (8/3) m4 for an isotropic Gaussian surface (Nayak 1971:
  // Cov(h_xx, h_yy) = m4/3, docs/theory.md 5.4); the curvature is half the Laplacian.
  c.rms_curvature = std::sqrt(8 * m.m4 / 3) / 2;
  c.range = law.reach();
  c.number = c.rms_gradient * estar * c.range / (2 * law.work) *
             std::pow(c.rms_gradient * c.rms_gradient / (c.rms_curvature * c.range), 2.0 / 3.0);
  return c;
}

std::string pastewka_robbins_text(const PastewkaRobbinsCriterion& c) {
  return "Pastewka-Robbins stickiness number C = (h'rms E* dr/(2w)) (h'rms^2/(h''rms dr))^(2/3) = " +
         format_number(c.number) + " with h'rms = " + format_number(c.rms_gradient) +
         ", h''rms = " + format_number(c.rms_curvature) + " 1/m, dr = " + format_number(c.range) +
         " m: " + (c.sticky() ? "sticky (C < 1)" : "not sticky (C >= 1)");
}

}  // namespace contactbench
