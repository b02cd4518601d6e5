// Persson's theory with a yield stress as a method of a scene (theories/persson_plastic.hpp): it reads m2 and
// the interface's hardness.
#include <memory>

#include "contactbench/app/methods/plastic_theory_method.hpp"
#include "contactbench/theories/persson_plastic.hpp"

namespace contactbench {

std::unique_ptr<Method> make_persson_plastic_method() {
  return std::make_unique<PlasticTheoryMethod>(
      "persson_plastic", "",
      [](const SpectralMoments& m, std::span<const Real> loads, const PlasticTheoryInputs& in) {
        return persson_plastic_curve(m, loads, in.hardness_over_estar);
      });
}

}  // namespace contactbench
