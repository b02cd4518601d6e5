#include "contactbench/app/output.hpp"

#include <iostream>

#include "contactbench/core/atomic_file.hpp"

namespace contactbench {

void write_output(const std::string& path, const std::function<void(std::ostream&)>& write) {
  if (path.empty()) {
    write(std::cout);
    std::cout.flush();
  } else {
    write_file_atomically(path, write);
  }
}

}  // namespace contactbench
