// Majumdar and Bhushan's elastic-plastic fractal model as a method of a scene
// (theories/majumdar_bhushan.hpp): D and G fitted to the surface's profile spectrum, the interface's
// hardness. Its criticisms are in docs/theory.md section 11.5.
#include <memory>

#include "contactbench/app/methods/plastic_theory_method.hpp"
#include "contactbench/theories/majumdar_bhushan.hpp"

namespace contactbench {

std::unique_ptr<Method> make_majumdar_bhushan_method() {
  return std::make_unique<PlasticTheoryMethod>(
      "majumdar_bhushan", "",
      [](const SpectralMoments&, std::span<const Real> loads, const PlasticTheoryInputs& in) {
        return majumdar_bhushan_curve(fit_fractal_parameters(*in.surface), loads, in.hardness_over_estar,
                                      in.nominal_area);
      });
}

}  // namespace contactbench
