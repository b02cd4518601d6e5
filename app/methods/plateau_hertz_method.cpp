// The Hertz-consistent plateaus, the PROJECT's variant of the multi-plateaus model and not the paper's
// (theories/plateau_hertz.hpp; docs/theory.md section 8.3): the paper's cut and spots, each spot's contact
// radius that of an elastic paraboloid of the same bearing radius. Same keys and sweep as `plateau`.
#include <memory>

#include "contactbench/app/methods/plateau_method.hpp"
#include "contactbench/theories/plateau_hertz.hpp"

namespace contactbench {

namespace {

class PlateauHertzMethod final : public PlateauMethod {
 public:
  std::string_view name() const override { return "plateau_hertz"; }
  // Every table and legend says that this is not the paper's model.
  std::string note() const override { return "Hertz-consistent plateaus, this project"; }
  std::string compared_area() const override {
    // The parameters (theories/plateau_hertz.cpp) and the table's row title already say it is not the
    // paper's model; saying it a third time here only lengthens the line.
    return "the Hertz-consistent area, half the bearing area of {h > z} at sqrt(2) x the load "
           "(docs/theory.md "
           "section 8.3)";
  }

  MethodCurve evaluate(const MethodInputs& in) const override {
    MethodCurve curve = MethodCurve::from(
        plateau_hertz_curve_at_loads(in.sweep->sweep, in.sweep->model, in.scene.loads), in.scene.loads);
    complete(curve, in);
    // Its own dP/dd (docs/theory.md 12.5): K_H = 2 E* sqrt(A_H N / pi) / A0, 1/sqrt(2) x the paper's model's.
    if (in.scene.compares(Quantity::stiffness)) {
      const Real a0 = in.surface.grid().nominal_area(), estar = in.scene.material.estar;
      for (std::size_t k = 0; k < curve.area_fraction.size(); ++k)
        curve.stiffness.push_back(estar *
                                  plateau_hertz_stiffness(curve.area_fraction[k], curve.spots[k], a0));
    }
    return curve;
  }
};

}  // namespace

std::unique_ptr<Method> make_plateau_hertz_method() {
  return std::make_unique<PlateauHertzMethod>();
}

}  // namespace contactbench
