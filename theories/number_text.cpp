#include "contactbench/theories/number_text.hpp"

#include <cstdio>

namespace contactbench {

std::string format_number(Real value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace contactbench
