// Numbers in the form the theories' parameter strings and messages use (%.6g).
#pragma once

#include <string>

#include "contactbench/core/types.hpp"

namespace contactbench {

std::string format_number(Real value);

}  // namespace contactbench
