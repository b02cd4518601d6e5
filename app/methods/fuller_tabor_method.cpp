// Fuller–Tabor (GW summits each a JKR sphere) as a method of a scene (theories/fuller_tabor.hpp): it takes
// any adhesion law through its work w alone.
#include <memory>

#include "contactbench/app/methods/adhesive_summit_method.hpp"
#include "contactbench/theories/fuller_tabor.hpp"

namespace contactbench {

std::unique_ptr<Method> make_fuller_tabor_method() {
  return std::make_unique<AdhesiveSummitMethod>(
      "fuller_tabor", "a JKR sphere",
      [](const SpectralMoments& m, Real estar, const AdhesionLaw& law, std::span<const Real> loads,
         AdhesiveBranch branch,
         Real area) { return fuller_tabor_curve(m, estar, law.work, loads, branch, area); });
}

}  // namespace contactbench
