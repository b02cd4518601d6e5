// Results that did not converge (docs/solvers.md): a run writes them, marked in every table and summary, and
// then exits with a status of its own, kUnconvergedExitStatus, unless each method with unconverged loads
// accepts them (the bem method's allow_unconverged = true, `contactbench bem --allow-unconverged`). A
// reference that did not converge is thus never passed off as the truth with exit status 0.
#pragma once

#include <string>
#include <vector>

#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

// The exit status of a run whose results were written but did not all converge (1 is any other error).
inline constexpr int kUnconvergedExitStatus = 3;

class UnconvergedError : public Error {
 public:
  using Error::Error;
};

// The loads (indices) where a method's iteration did not converge (MethodCurve::converged); none for methods
// that do not iterate.
std::vector<std::size_t> unconverged_loads(const MethodCurve& curve);

// "bem at P/(E* A0) = 0.001, 0.01 (did not converge)": the methods' unconverged loads, those accepted too;
// empty when every load converged.
std::string describe_unconverged(const SceneReport& report);

// Throws UnconvergedError naming the loads, when a method that does not accept them has unconverged loads.
void throw_if_unconverged(const SceneReport& report);

}  // namespace contactbench
