#include "contactbench/core/scales.hpp"

#include <cmath>
#include <sstream>

namespace contactbench {

bool within_magnitudes(Real value) {
  const Real size = std::abs(value);
  return size == 0 || (size >= kSmallestMagnitude && size <= kLargestMagnitude);
}

std::string magnitude_problem(const std::string& what, Real value, const std::string& unit) {
  std::ostringstream text;
  text << what << " " << value << " " << unit << " lies outside 1e-100 to 1e100 " << unit
       << ", where sums of its squares stay within double precision";
  return text.str();
}

}  // namespace contactbench
