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
      true,
      // The summit model's mean gap is the flat's separation from the mean plane of the heights (the
      // surface between summits is undeformed and the summits' deformation is local: docs/theory.md
      // 12.4), and its stiffness the analytic -dP/dd.
      [](const SpectralMoments& m, const MethodInputs& in, MethodCurve& curve) {
        const GwParameters gw = mccool_parameters(m);
        curve.mean_gap = curve.separation;
        for (const Real d : curve.separation)
          curve.stiffness.push_back(in.scene.material.estar * gw_stiffness(gw, (d - gw.ys) / gw.sigma_s));
      });
}

}  // namespace contactbench
