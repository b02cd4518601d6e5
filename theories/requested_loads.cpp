#include "contactbench/theories/requested_loads.hpp"

#include <cmath>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

void validate_loads(std::span<const Real> loads, std::string_view method) {
  for (std::size_t i = 0; i < loads.size(); ++i) {
    if (!(std::isfinite(loads[i]) && loads[i] > 0))
      throw Error(std::string(method) + ": a load P/(E* A0) must be finite and > 0, got " +
                  format_number(loads[i]) + " at position " + std::to_string(i));
    if (i > 0 && loads[i] < loads[i - 1])
      throw Error(std::string(method) + ": loads must be ascending, got " + format_number(loads[i]) +
                  " at position " + std::to_string(i) + " after " + format_number(loads[i - 1]));
  }
}

}  // namespace contactbench
