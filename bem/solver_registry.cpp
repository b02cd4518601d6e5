#include "contactbench/bem/solver_registry.hpp"

#include "contactbench/core/error.hpp"

namespace contactbench {

const std::vector<std::string>& solver_names() {
  static const std::vector<std::string> names{"polonsky_keer", "preconditioned_cg", "active_set"};
  return names;
}

std::string_view solver_name(SolverKind kind) {
  return solver_names().at(static_cast<std::size_t>(kind));
}

SolverKind solver_kind(std::string_view name, std::string_view where) {
  const std::vector<std::string>& names = solver_names();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<SolverKind>(k);
  std::string known;
  for (const std::string& n : names)
    known += (known.empty() ? "" : ", ") + n;
  throw Error(std::string(where) + ": unknown BEM solver \"" + std::string(name) +
              "\"; known solvers: " + known);
}

}  // namespace contactbench
