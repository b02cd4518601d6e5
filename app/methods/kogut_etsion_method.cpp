// Kogut-Etsion (2002) summits on McCool's GW statistics as a method of a scene (theories/kogut_etsion.hpp):
// it reads m0, m2, m4, the interface's hardness and the material's nu (0.3 when the scene gives none).
#include <memory>

#include "contactbench/app/methods/plastic_theory_method.hpp"
#include "contactbench/theories/kogut_etsion.hpp"

namespace contactbench {

std::unique_ptr<Method> make_kogut_etsion_method() {
  return std::make_unique<PlasticTheoryMethod>(
      "kogut_etsion", "",
      [](const SpectralMoments& m, std::span<const Real> loads, const PlasticTheoryInputs& in) {
        return kogut_etsion_curve(m, loads, in.hardness_over_estar, in.poisson_ratio, in.nominal_area);
      });
}

}  // namespace contactbench
