// The plateau models with a yield limit, the PROJECT's extensions and not the paper's model
// (theories/plateau_capped.hpp; docs/theory.md section 11.2): the same keys and sweep as `plateau`, each
// plateau's mean pressure capped at the interface's hardness. Two methods, plateau_capped (the paper's
// reading) and plateau_hertz_capped (the Hertz-consistent reading), apart from `plateau` and `plateau_hertz`
// so that a scene's elastic rows keep the paper's model untouched and every table names the variant.
#include <memory>

#include "contactbench/app/methods/plastic_theory_method.hpp"
#include "contactbench/app/methods/plateau_method.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/theories/plateau_capped.hpp"

namespace contactbench {

namespace {

class PlateauCappedMethod final : public PlateauMethod {
 public:
  explicit PlateauCappedMethod(PlateauReading reading) : reading_(reading) {}

  std::string_view name() const override {
    return reading_ == PlateauReading::hertz ? "plateau_hertz_capped" : "plateau_capped";
  }
  std::vector<Effect> models() const override { return {Effect::hardness}; }
  std::string note() const override {
    return reading_ == PlateauReading::hertz ? "Hertz-consistent plateaus capped at H, this project"
                                             : "plateaus capped at H, this project";
  }
  std::string compared_area() const override {
    return reading_ == PlateauReading::hertz
               ? "max(A_c/2, P/H), the Hertz-consistent area spread plastically up to the bearing area "
                 "(docs/theory.md "
                 "section 11.2)"
               : "the bearing area of {h > z}, at the load capped by H A_c (docs/theory.md section 11.2)";
  }
  void read(const Section& keys, const SceneContext& context) override {
    PlateauMethod::read(keys, context);
    hardness_ = context.interface.hardness;
  }
  void preflight(const MethodCheck& check) const override {
    PlateauMethod::preflight(check);
    check_hardness_against_loads(check);
  }
  MethodCurve evaluate(const MethodInputs& in) const override {
    const Real h = hardness_ ? *hardness_ / in.scene.material.estar : kNoHardness;
    const PlasticCurve plastic =
        plateau_capped_curve_at_loads(in.sweep->sweep, in.sweep->model, in.scene.loads, h, reading_);
    MethodCurve curve = MethodCurve::from(plastic.curve, in.scene.loads);
    complete(curve, in);
    if (reading_ == PlateauReading::paper) {
      curve.area_fraction_nodes = curve.area_fraction;  // the bearing area, a node count
      curve.columns.emplace_back("area_fraction_nodes", curve.area_fraction);
    }
    curve.columns.emplace_back("plastic_area_fraction", plastic.plastic_area_fraction);
    curve.columns.emplace_back("plastic_load_fraction", plastic.plastic_load_fraction);
    return curve;
  }

 private:
  PlateauReading reading_;
  std::optional<Real> hardness_;  // [Pa]
};

}  // namespace

std::unique_ptr<Method> make_plateau_capped_method() {
  return std::make_unique<PlateauCappedMethod>(PlateauReading::paper);
}
std::unique_ptr<Method> make_plateau_hertz_capped_method() {
  return std::make_unique<PlateauCappedMethod>(PlateauReading::hertz);
}

}  // namespace contactbench
