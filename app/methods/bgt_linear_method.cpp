// The BGT linear law as a method of a scene (theories/bgt_linear.hpp): it reads m2 alone.
#include <memory>

#include "contactbench/app/methods/theory_method.hpp"
#include "contactbench/theories/bgt_linear.hpp"

namespace contactbench {

std::unique_ptr<Method> make_bgt_linear_method() {
  return std::make_unique<AnalyticTheoryMethod>(
      "bgt_linear",
      [](const SpectralMoments& m, std::span<const Real> loads, Real) { return bgt_linear_curve(m, loads); },
      false);
}

}  // namespace contactbench
