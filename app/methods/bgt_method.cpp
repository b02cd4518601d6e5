// The full Bush-Gibson-Thomas model as a method of a scene (theories/bush_gibson_thomas.hpp).
#include <memory>

#include "contactbench/app/methods/theory_method.hpp"
#include "contactbench/theories/bush_gibson_thomas.hpp"

namespace contactbench {

std::unique_ptr<Method> make_bgt_method() {
  return std::make_unique<AnalyticTheoryMethod>(
      "bgt",
      [](const SpectralMoments& m, std::span<const Real> loads, Real area) {
        return bgt_curve(m, loads, area);
      },
      true);
}

}  // namespace contactbench
