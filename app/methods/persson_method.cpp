// Persson's theory at full magnification as a method of a scene (theories/persson.hpp): it reads m2 alone.
#include <memory>

#include "contactbench/app/methods/theory_method.hpp"
#include "contactbench/theories/persson.hpp"
#include "contactbench/theories/persson_gap.hpp"

namespace contactbench {

std::unique_ptr<Method> make_persson_method() {
  return std::make_unique<AnalyticTheoryMethod>(
      "persson",
      [](const SpectralMoments& m, std::span<const Real> loads, Real) { return persson_curve(m, loads); },
      false,
      // u-bar(p) of Persson 2007 and Yang-Persson 2008 and its -dp/du-bar (theories/persson_gap.hpp) over the
      // surface's own spectrum: one transform of the surface, made only when the scene compares them.
      [](const SpectralMoments&, const MethodInputs& in, MethodCurve& curve) {
        const PerssonGap persson(fourier_coefficients(in.surface));
        for (const Real load : in.scene.loads) {
          curve.mean_gap.push_back(persson.mean_gap(load));
          curve.stiffness.push_back(in.scene.material.estar * persson.stiffness(load));
        }
        curve.parameters += "; mean gap and stiffness with gamma = " + std::to_string(persson.gamma()) +
                            " over the surface's lattice spectrum";
      },
      true);
}

}  // namespace contactbench
