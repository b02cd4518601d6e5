#include "contactbench/app/unconverged.hpp"

#include <algorithm>

#include "contactbench/app/json_writer.hpp"

namespace contactbench {

namespace {

std::string loads_of(const SceneReport& report, const MethodResult& method) {
  std::string text;
  for (const std::size_t k : unconverged_loads(method.curve))
    text += (text.empty() ? "" : ", ") + json_number(report.loads()[k]);
  return text;
}

// "the approach-retract path (3 of 82 states)", or "" when the method has no path or every state converged.
std::string path_of(const MethodCurve& curve) {
  if (!curve.approach_retract || curve.approach_retract->converged) return "";
  const auto& states = curve.approach_retract->states;
  const auto failed = std::count_if(states.begin(), states.end(), [](const auto& s) { return !s.converged; });
  return "the approach-retract path (" + std::to_string(failed) + " of " + std::to_string(states.size()) +
         " states)";
}

// What of one method did not converge: its loads, its path, or both; "" when everything did.
std::string unconverged_of(const SceneReport& report, const MethodResult& m) {
  std::string text;
  if (!unconverged_loads(m.curve).empty()) text = "at P/(E* A0) = " + loads_of(report, m);
  const std::string path = path_of(m.curve);
  if (!path.empty()) text += (text.empty() ? "" : " and ") + path;
  return text.empty() ? "" : m.label + " " + text;
}

}  // namespace

std::vector<std::size_t> unconverged_loads(const MethodCurve& curve) {
  std::vector<std::size_t> loads;
  for (std::size_t k = 0; k < curve.converged.size(); ++k)
    if (!curve.converged[k]) loads.push_back(k);
  return loads;
}

std::string describe_unconverged(const SceneReport& report) {
  std::string text;
  for (const MethodResult& m : report.methods)
    if (const std::string what = unconverged_of(report, m); !what.empty())
      text += (text.empty() ? "" : "; ") + what +
              (m.curve.accepts_unconverged ? " (accepted: allow_unconverged = true)" : "");
  return text;
}

void throw_if_unconverged(const SceneReport& report) {
  std::string refused;
  for (const MethodResult& m : report.methods)
    if (const std::string what = unconverged_of(report, m); !m.curve.accepts_unconverged && !what.empty())
      refused += (refused.empty() ? "" : "; ") + what;
  if (refused.empty()) return;
  throw UnconvergedError("did not converge: " + refused +
                         ". The results are written and marked 'not converged'; raise max_iterations "
                         "(--max-iterations), or accept them with allow_unconverged = true in the method "
                         "(--allow-unconverged)");
}

}  // namespace contactbench
