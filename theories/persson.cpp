#include "contactbench/theories/persson.hpp"

#include <cmath>
#include <numbers>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/theory_curve.hpp"

namespace contactbench {

// Persson (2001), docs/theory.md section 5: A/A0 = erf(p/(E* sqrt(m2))).
Real persson_area_fraction(Real load, Real m2) {
  return std::erf(load / std::sqrt(m2));
}

// Persson (2001): A/A0 = erf(p/(2 sqrt(G))), G = (pi/4) E*^2 int q^3 C dq.
Real persson_area_fraction_psd(Real load, Real q3_integral) {
  const Real g_over_estar2 = std::numbers::pi / 4 * q3_integral;
  return std::erf(load / (2 * std::sqrt(g_over_estar2)));
}

Real persson_q3_integral(const FourierCoefficients& c) {
  const HalfLattice lattice(c.grid);
  const auto psd = psd_2d(c);
  const Real cell = c.grid.dqx() * c.grid.dqy();
  // Neumaier's compensated sum: the result is then exact to round-off whatever the number of modes.
  Real sum = 0, compensation = 0;
  for (Index row = 0; row < lattice.rows(); ++row) {
    const Real qy = lattice.qy(row);
    for (Index col = 0; col < lattice.cols(); ++col) {
      const Real qx = lattice.qx(col);
      const Real term = lattice.multiplicity(col) * (qx * qx + qy * qy) * psd(row, col) * cell;
      const Real next = sum + term;
      compensation += std::abs(sum) >= std::abs(term) ? (sum - next) + term : (term - next) + sum;
      sum = next;
    }
  }
  return (sum + compensation) / (2 * std::numbers::pi);
}

LoadAreaCurve persson_curve(const SpectralMoments& moments, std::span<const Real> loads) {
  TheoryCurve curve("persson");
  const Real m2 = isotropic_m2(moments, curve.method());
  curve.check_request(loads);
  for (const Real load : loads)
    curve.add(load, persson_area_fraction(load, m2));
  return curve.finish(profile_m2_text(m2) +
                      "; A/A0 = erf(P/(E* A0 sqrt(m2))) (Persson 2001, full magnification)");
}

}  // namespace contactbench
