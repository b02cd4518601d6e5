#include "contactbench/bem/solver_registry.hpp"

#include "contactbench/bem/solvers/active_set_solver.hpp"
#include "contactbench/bem/solvers/polonsky_keer_solver.hpp"
#include "contactbench/bem/solvers/preconditioned_cg_solver.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

const std::vector<SolverEntry>& solver_registry() {
  // Each solver's file holds its entry; a new solver adds its line here.
  static const std::vector<SolverEntry> entries{polonsky_keer_entry(), preconditioned_cg_entry(),
                                                active_set_entry()};
  return entries;
}

const SolverEntry& solver_entry(SolverKind kind) {
  for (const SolverEntry& entry : solver_registry())
    if (entry.kind == kind) return entry;
  throw Error("BEM solver registry: no solver registered for this kind");
}

const std::vector<std::string>& solver_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all;
    for (const SolverEntry& entry : solver_registry())
      all.emplace_back(entry.name);
    return all;
  }();
  return names;
}

std::string_view load_path_start_name(LoadPathStart start) {
  switch (start) {
    case LoadPathStart::scaled:
      return "scaled";
    case LoadPathStart::extrapolated:
      return "extrapolated";
    case LoadPathStart::cold:
      return "cold";
    case LoadPathStart::solver:
      return "solver";
  }
  return "?";
}

std::string_view solver_name(SolverKind kind) {
  return solver_entry(kind).name;
}

SolverKind solver_kind(std::string_view name, std::string_view where) {
  for (const SolverEntry& entry : solver_registry())
    if (entry.name == name) return entry.kind;
  std::string known;
  for (const std::string& n : solver_names())
    known += (known.empty() ? "" : ", ") + n;
  throw Error(std::string(where) + ": unknown BEM solver \"" + std::string(name) +
              "\"; known solvers: " + known);
}

}  // namespace contactbench
