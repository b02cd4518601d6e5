// Maugis–GW (GW summits each a Maugis–Dugdale sphere) as a method of a scene
// (theories/maugis_greenwood_williamson.hpp): the Dugdale law as given, the exponential law through its
// equal-work, equal-peak-stress Dugdale law.
#include <memory>

#include "contactbench/app/methods/adhesive_summit_method.hpp"
#include "contactbench/theories/maugis_greenwood_williamson.hpp"

namespace contactbench {

std::unique_ptr<Method> make_maugis_gw_method() {
  return std::make_unique<AdhesiveSummitMethod>(
      "maugis_gw", "a Maugis-Dugdale sphere",
      [](const SpectralMoments& m, Real estar, const AdhesionLaw& law, std::span<const Real> loads,
         AdhesiveBranch branch, Real area) { return maugis_gw_curve(m, estar, law, loads, branch, area); });
}

}  // namespace contactbench
