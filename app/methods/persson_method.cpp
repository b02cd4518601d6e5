// Persson's theory at full magnification as a method of a scene (theories/persson.hpp): it reads m2 alone.
#include <memory>

#include "contactbench/app/methods/theory_method.hpp"
#include "contactbench/theories/persson.hpp"

namespace contactbench {

std::unique_ptr<Method> make_persson_method() {
  return std::make_unique<AnalyticTheoryMethod>(
      "persson",
      [](const SpectralMoments& m, std::span<const Real> loads, Real) { return persson_curve(m, loads); },
      false);
}

}  // namespace contactbench
