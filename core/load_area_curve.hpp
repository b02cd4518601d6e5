// The one currency between modules (docs/architecture.md): a load-area curve in the dimensionless form
// A/A0 against P/(E* A0), with the method's name, its parameters and the wall time it cost.
#pragma once

#include <string>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

struct LoadAreaCurve {
  std::string method;               // e.g. "plateau"
  std::string parameters;           // e.g. "4-connectivity, not periodic, exact levels"
  std::vector<Real> load;           // P / (E* A0), ascending
  std::vector<Real> area_fraction;  // A / A0
  std::vector<Real> separation;     // z [m] where the method has one (NaN otherwise)
  std::vector<Real> spots;          // contact spots where the method counts them (NaN otherwise)
  double seconds = 0;               // wall time of the computation behind the curve
};

}  // namespace contactbench
