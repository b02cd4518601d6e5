#include "contactbench/app/methods/adhesive_summit_method.hpp"

#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/theories/pastewka_robbins_criterion.hpp"

namespace contactbench {

void AdhesiveSummitMethod::read(const Section& s, const SceneContext&) {
  s.reject_unknown({"method", "branch"});
  branch_ = s.choice("branch", {"approach", "retract"}) == "retract" ? AdhesiveBranch::retract
                                                                     : AdhesiveBranch::approach;
}

void AdhesiveSummitMethod::write(SceneKeys& keys) const {
  keys.put("branch", std::string(adhesive_branch_name(branch_)));
}

MethodNeeds AdhesiveSummitMethod::needs(const SceneContext&) const {
  return {.moments = true, .sweep = std::nullopt, .bem = std::nullopt, .bem_connectivity = 4};
}

void AdhesiveSummitMethod::preflight(const MethodCheck& check) const {
  const std::string table = "[" + check.key + "]";
  if (!check.interface.adhesion) {
    check.problems.add(
        0, "interface.adhesion",
        "the method " + name_ +
            " is an adhesive theory: it needs the interface's adhesion, and this scene "
            "(or its ignore list in " +
            table + ") has none",
        "interface.adhesion = { model = \"dugdale\", work = <w>, stress = <sigma0> } or { model "
        "= \"exponential\", work = <w>, range = <rho> }, or a non-adhesive theory (gw_mccool)");
    return;
  }
  if (check.interface.hardness) {
    check.problems.add(0, "interface.hardness",
                       "the method " + name_ + " models elastic summits: it does not model a hardness",
                       "no interface.hardness, or leave " + table + " out");
    return;
  }
  try {
    curve_(check.moments, check.scene.material.estar, *check.interface.adhesion, check.scene.loads, branch_,
           check.surface.grid().nominal_area());
  } catch (const Error& error) {
    check.problem("", error.what(),
                  "loads the theory reaches on its branch (loads.values or loads.range), an isotropic "
                  "surface, or leave this method out");
  }
}

MethodCurve AdhesiveSummitMethod::evaluate(const MethodInputs& in) const {
  const AdhesionLaw& law = *in.scene.interface.adhesion;
  MethodCurve curve = MethodCurve::from(curve_(in.moments, in.scene.material.estar, law, in.scene.loads,
                                               branch_, in.surface.grid().nominal_area()),
                                        in.scene.loads);
  // Whether the scene's surface sticks at all, by a criterion that is not the summits' (docs/theory.md 10.5).
  curve.parameters +=
      "; " + pastewka_robbins_text(pastewka_robbins_criterion(in.moments, in.scene.material.estar, law));
  return curve;
}

}  // namespace contactbench
