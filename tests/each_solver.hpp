// Runs a test once per boundary-element solver (bem/solver_registry.hpp): the validations are the same
// physics whatever the iteration, so every solver must pass every one of them. A suite derives its fixture
// from EachSolver, writes TEST_P and passes `.solver = GetParam()` to the solver's options, and ends with
// CB_FOR_EACH_SOLVER(Suite).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "contactbench/bem/solver_registry.hpp"

namespace contactbench {

class EachSolver : public ::testing::TestWithParam<SolverKind> {};

inline std::vector<SolverKind> every_solver() {
  std::vector<SolverKind> kinds;
  for (const std::string& name : solver_names())
    kinds.push_back(solver_kind(name));
  return kinds;
}

inline std::string solver_test_name(const ::testing::TestParamInfo<SolverKind>& info) {
  return std::string(solver_name(info.param));
}

}  // namespace contactbench

#define CB_FOR_EACH_SOLVER(suite)                                                        \
  INSTANTIATE_TEST_SUITE_P(, suite, ::testing::ValuesIn(::contactbench::every_solver()), \
                           ::contactbench::solver_test_name)
