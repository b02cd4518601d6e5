// Chang-Etsion-Bogy (1987) summits on McCool's GW statistics as a method of a scene
// (theories/chang_etsion_bogy.hpp): it reads m0, m2, m4, the interface's hardness and the material's nu (0.3
// when the scene gives none).
#include <memory>

#include "contactbench/app/methods/plastic_theory_method.hpp"
#include "contactbench/theories/chang_etsion_bogy.hpp"

namespace contactbench {

std::unique_ptr<Method> make_ceb_method() {
  return std::make_unique<PlasticTheoryMethod>(
      "ceb", "", [](const SpectralMoments& m, std::span<const Real> loads, const PlasticTheoryInputs& in) {
        return chang_etsion_bogy_curve(m, loads, in.hardness_over_estar, in.poisson_ratio, in.nominal_area);
      });
}

}  // namespace contactbench
