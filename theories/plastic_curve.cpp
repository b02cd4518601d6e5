#include "contactbench/theories/plastic_curve.hpp"

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

void check_hardness(Real h, std::span<const Real> loads, std::string_view method) {
  if (!(h > 0) || std::isnan(h))
    throw Error(std::string(method) + ": the hardness H/E* must be > 0, got " + format_number(h));
  std::string refused;
  for (std::size_t k = 0; k < loads.size(); ++k)
    if (loads[k] >= h)
      refused +=
          (refused.empty() ? "" : ", ") + format_number(loads[k]) + " (load " + std::to_string(k + 1) + ")";
  if (!refused.empty())
    throw Error(std::string(method) + ": the hardness H/E* = " + format_number(h) +
                " is at or below the mean pressure P/(E* A0) of the loads " + refused +
                ": the whole nominal area would be plastic (A/A0 = P/(H A0) >= 1)");
}

}  // namespace contactbench
