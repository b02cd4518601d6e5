// The full Bush-Gibson-Thomas model as a method of a scene (theories/bush_gibson_thomas.hpp).
#include <memory>

#include "contactbench/app/methods/theory_method.hpp"
#include "contactbench/theories/bush_gibson_thomas.hpp"
#include "contactbench/theories/isotropic_moments.hpp"

namespace contactbench {

std::unique_ptr<Method> make_bgt_method() {
  return std::make_unique<AnalyticTheoryMethod>(
      "bgt",
      [](const SpectralMoments& m, std::span<const Real> loads, Real area) {
        return bgt_curve(m, loads, area);
      },
      true,
      // As GW's (docs/theory.md 12.4): the separation as the mean gap, the analytic -dP/dd.
      [](const SpectralMoments& m, const MethodInputs& in, MethodCurve& curve) {
        const BushGibsonThomas model(isotropic_moments(m, "bgt"));
        curve.mean_gap = curve.separation;
        for (const Real d : curve.separation)
          curve.stiffness.push_back(in.scene.material.estar * model.stiffness(d));
      });
}

}  // namespace contactbench
