// The adhesive plateaus, the PROJECT's adhesive readings of the multi-plateaus model and not the paper's
// (theories/adhesive_plateaus.hpp; docs/theory.md section 10.6): `plateau_kendall`, the paper's plateaus as
// adhesive flat punches, and `plateau_hertz_jkr`, the Hertz-consistent plateaus as JKR contacts. The same
// keys and sweep as `plateau`; they model the interface's adhesion (through its work w alone) and need it.
#include <memory>
#include <string>

#include "contactbench/app/methods/plateau_method.hpp"
#include "contactbench/app/problems.hpp"
#include "contactbench/theories/adhesive_plateaus.hpp"

namespace contactbench {

namespace {

class AdhesivePlateauMethod final : public PlateauMethod {
 public:
  explicit AdhesivePlateauMethod(AdhesivePlateauSpot spot) : spot_(spot) {}

  std::string_view name() const override {
    return spot_ == AdhesivePlateauSpot::kendall_punch ? "plateau_kendall" : "plateau_hertz_jkr";
  }
  std::vector<Effect> models() const override { return {Effect::adhesion}; }
  // Every table and legend says that this is the project's reading, not the paper's model.
  std::string note() const override {
    return spot_ == AdhesivePlateauSpot::kendall_punch
               ? "plateaus as Kendall punches, this project"
               : "Hertz-consistent plateaus as JKR contacts, this project";
  }
  std::string compared_area() const override {
    return spot_ == AdhesivePlateauSpot::kendall_punch
               ? "the bearing area of {h > z} at the first level whose adhesive load reaches the load"
               : "half the bearing area of {h > z} at the first level whose adhesive load reaches the load";
  }

  void preflight(const MethodCheck& check) const override {
    PlateauMethod::preflight(check);
    const std::string table = "[" + check.key + "]";
    if (!check.interface.adhesion)
      check.problems.add(
          0, "interface.adhesion",
          "the method " + std::string(name()) +
              " is an adhesive model: it needs the interface's adhesion, and this scene (or its "
              "ignore list in " +
              table + ") has none",
          "interface.adhesion = { model = ..., work = <w>, ... }, or plateau / plateau_hertz");
    else if (check.interface.hardness)
      check.problems.add(
          0, "interface.hardness",
          "the method " + std::string(name()) + " models elastic spots: it does not model a hardness",
          "no interface.hardness, or leave " + table + " out");
  }

  MethodCurve evaluate(const MethodInputs& in) const override {
    MethodCurve curve = MethodCurve::from(
        adhesive_plateau_curve_at_loads(in.sweep->sweep, in.sweep->model, in.scene.material.estar,
                                        in.scene.interface.adhesion->work, spot_, in.scene.loads),
        in.scene.loads);
    complete(curve, in);
    return curve;
  }

 private:
  AdhesivePlateauSpot spot_;
};

}  // namespace

std::unique_ptr<Method> make_plateau_kendall_method() {
  return std::make_unique<AdhesivePlateauMethod>(AdhesivePlateauSpot::kendall_punch);
}

std::unique_ptr<Method> make_plateau_hertz_jkr_method() {
  return std::make_unique<AdhesivePlateauMethod>(AdhesivePlateauSpot::jkr_paraboloid);
}

}  // namespace contactbench
