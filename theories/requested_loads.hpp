// The loads a theory is asked for: P/(E* A0), finite, > 0 and ascending.
#pragma once

#include <span>
#include <string_view>

#include "contactbench/core/types.hpp"

namespace contactbench {

// Refuses (Error naming `method`, the value and its position) a load that is not finite and > 0 or that is
// below its predecessor.
void validate_loads(std::span<const Real> loads, std::string_view method);

}  // namespace contactbench
