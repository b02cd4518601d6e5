#include "contactbench/app/unconverged.hpp"

#include "contactbench/app/json_writer.hpp"

namespace contactbench {

namespace {

std::string loads_of(const SceneReport& report, const MethodResult& method) {
  std::string text;
  for (const std::size_t k : unconverged_loads(method.curve))
    text += (text.empty() ? "" : ", ") + json_number(report.loads()[k]);
  return text;
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
    if (!unconverged_loads(m.curve).empty())
      text += (text.empty() ? "" : "; ") + m.label + " at P/(E* A0) = " + loads_of(report, m) +
              (m.curve.accepts_unconverged ? " (accepted: allow_unconverged = true)" : "");
  return text;
}

void throw_if_unconverged(const SceneReport& report) {
  std::string refused;
  for (const MethodResult& m : report.methods)
    if (!m.curve.accepts_unconverged && !unconverged_loads(m.curve).empty())
      refused += (refused.empty() ? "" : "; ") + m.label + " at P/(E* A0) = " + loads_of(report, m);
  if (refused.empty()) return;
  throw UnconvergedError("did not converge: " + refused +
                         ". The results are written and marked 'not converged'; raise max_iterations "
                         "(--max-iterations), or accept them with allow_unconverged = true in the method "
                         "(--allow-unconverged)");
}

}  // namespace contactbench
