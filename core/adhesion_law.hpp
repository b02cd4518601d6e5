// The attraction between the surfaces as a function of their local gap g (docs/theory.md section 10): the
// traction an adhesive interface adds to the repulsive contact pressure, pulling the surfaces together. Two
// laws, both with the work of adhesion w = Δγ [J/m^2] as the integral of the attraction over the gap:
// - Maugis–Dugdale: a constant stress σ0 while g < δc = w/σ0, nothing beyond (Maugis 1992);
// - exponential: (w/ρ) exp(-g/ρ), the short-range interaction of the contact-mechanics challenge (Müser and
//   Dapp, arXiv:1512.02403, whose range is ρ and whose peak stress is w/ρ).
// The Tabor parameter of a sphere of radius R compares the elastic neck with the range of the attraction.
#pragma once

#include <cmath>
#include <sstream>
#include <string>
#include <string_view>

#include "contactbench/core/error.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

enum class AdhesionModel { dugdale, exponential };

struct AdhesionLaw {
  AdhesionModel model = AdhesionModel::dugdale;
  Real work = 0;    // w = Δγ [J/m^2], > 0
  Real stress = 0;  // σ0 [Pa] (dugdale), > 0
  Real range = 0;   // ρ [m] (exponential), > 0

  static AdhesionLaw dugdale(Real work, Real stress) { return {AdhesionModel::dugdale, work, stress, 0}; }
  static AdhesionLaw exponential(Real work, Real range) {
    return {AdhesionModel::exponential, work, 0, range};
  }

  // The attraction [Pa, >= 0] at a gap g >= 0 [m].
  Real attraction(Real gap) const {
    if (model == AdhesionModel::dugdale) return gap < work / stress ? stress : 0;
    return work / range * std::exp(-gap / range);
  }
  // The largest attraction [Pa]: σ0, or w/ρ at contact.
  Real peak_stress() const { return model == AdhesionModel::dugdale ? stress : work / range; }
  // The gap [m] over which the attraction acts: δc = w/σ0, or ρ (where it has fallen by e).
  Real reach() const { return model == AdhesionModel::dugdale ? work / stress : range; }

  // Maugis' parameter λ = 2 σ0 (9R/(16π w E*^2))^(1/3) of a sphere of radius R [m] on a half-space of
  // contact modulus E* [Pa], with the peak stress as σ0 (Johnson & Greenwood 1997, with K = 4E*/3;
  // Tabor's μ = 1.16 λ).
  Real maugis_parameter(Real radius, Real modulus) const {
    return 2 * peak_stress() * std::cbrt(9 * radius / (16 * M_PI * work * modulus * modulus));
  }

  bool operator==(const AdhesionLaw&) const = default;
};

inline std::string_view adhesion_model_name(AdhesionModel model) {
  return model == AdhesionModel::dugdale ? "dugdale" : "exponential";
}

// Throws Error naming `what` unless the law's numbers are finite and > 0.
inline void validate_adhesion_law(const AdhesionLaw& law, const std::string& what) {
  const auto positive = [&](Real value, const char* name) {
    if (std::isfinite(value) && value > 0) return;
    std::ostringstream text;
    text << what << ": the adhesion's " << name << " must be finite and > 0, got " << value;
    throw Error(text.str());
  };
  positive(law.work, "work of adhesion [J/m^2]");
  if (law.model == AdhesionModel::dugdale)
    positive(law.stress, "stress sigma0 [Pa]");
  else
    positive(law.range, "range rho [m]");
}

}  // namespace contactbench
