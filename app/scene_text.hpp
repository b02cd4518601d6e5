// How a scene's values and names are written in messages and outputs: numbers exactly, lists joined, names
// portable (they become folder, column and file names).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

// Shortest decimal that reads back to the same double (messages must not round a value into the range).
std::string exact_number(Real value);
std::string join(const std::vector<std::string>& items);

// Names become folder names (results/<name>/) and labels become column and file names: keep them portable.
bool portable_name(std::string_view name, bool allow_dot);

}  // namespace contactbench
