#include "contactbench/app/methods/method.hpp"

#include <algorithm>
#include <cmath>

#include "contactbench/app/problems.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

void MethodCheck::problem(std::string_view key_suffix, std::string_view reason,
                          std::string_view accepted) const {
  problems.add(0, key_suffix.empty() ? key : key + "." + std::string(key_suffix), reason, accepted);
}

const std::vector<Real>& MethodCurve::values(Quantity quantity) const {
  switch (quantity) {
    case Quantity::mean_gap:
      return mean_gap;
    case Quantity::stiffness:
      return stiffness;
    case Quantity::area:
      break;
  }
  return area_fraction;
}

MethodCurve MethodCurve::from(const LoadAreaCurve& curve, const std::vector<Real>& loads) {
  // The library solves each load to 1e-12 relative (e.g. theories/greenwood_williamson.hpp); a curve at other
  // loads is a bug, never something to line up silently.
  constexpr Real kSameLoad = 1e-9;
  bool same = curve.load.size() == loads.size() && curve.area_fraction.size() == loads.size();
  for (std::size_t k = 0; same && k < loads.size(); ++k)
    same = std::abs(curve.load[k] - loads[k]) <= kSameLoad * loads[k];
  if (!same)
    throw Error("internal: the " + curve.method + " curve is not at the scene's " +
                std::to_string(loads.size()) + " loads");
  const auto per_load = [&](const std::vector<Real>& values) {
    return values.empty() ? std::vector<Real>(loads.size(), std::nan("")) : values;
  };
  MethodCurve answer;
  answer.area_fraction = curve.area_fraction;
  answer.separation = per_load(curve.separation);
  answer.spots = per_load(curve.spots);
  answer.parameters = curve.parameters;
  return answer;
}

void check_hardness_above_loads(const MethodCheck& check, const std::string& consequence) {
  const std::optional<Real> hardness = check.interface.hardness;
  if (!hardness) return;
  std::vector<std::string> refused;
  for (std::size_t k = 0; k < check.scene.loads.size(); ++k)
    if (check.scene.loads[k] * check.scene.material.estar >= *hardness)
      refused.push_back(exact_number(check.scene.loads[k]) + " (load " + std::to_string(k + 1) + ")");
  if (!refused.empty())
    check.problems.add(
        0, "interface.hardness",
        "the hardness " + exact_number(*hardness) +
            " Pa is at or below the mean pressure P/A0 = load E* of the loads " + join(refused) + consequence,
        "a hardness above " + exact_number(check.scene.loads.back() * check.scene.material.estar) +
            " Pa (the largest load times E*), or loads below hardness/E*");
}

void report_loads_the_theory_refuses(const MethodCheck& check,
                                     const std::function<void(Real)>& solve_one_load) {
  std::vector<std::string> reasons;
  for (const Real load : check.scene.loads) {
    try {
      solve_one_load(load);
    } catch (const Error& error) {
      if (std::find(reasons.begin(), reasons.end(), error.what()) == reasons.end())
        reasons.push_back(error.what());
    }
  }
  for (const std::string& reason : reasons)
    check.problem("", reason,
                  "loads the theory reaches (loads.values or loads.range), or leave this method out");
}

}  // namespace contactbench
