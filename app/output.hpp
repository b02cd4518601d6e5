// Where a command's text output goes: standard output, or a file written to a temporary name and renamed.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace contactbench {

// write(stream) to standard output when `path` is empty, else to `path` atomically (core/atomic_file.hpp).
void write_output(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace contactbench
