// Greenwood-Williamson with McCool's parameters as a method of a scene (theories/greenwood_williamson.hpp).
#include <memory>

#include "contactbench/app/methods/theory_method.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"

namespace contactbench {

std::unique_ptr<Method> make_gw_mccool_method() {
  return std::make_unique<AnalyticTheoryMethod>(
      "gw_mccool",
      [](const SpectralMoments& m, std::span<const Real> loads, Real area) {
        return gw_mccool_curve(m, loads, area);
      },
      true);
}

}  // namespace contactbench
