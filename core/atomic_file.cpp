#include "contactbench/core/atomic_file.hpp"

#include <atomic>
#include <fstream>
#include <string>
#include <system_error>

#include <unistd.h>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {
// A temporary name unique within this process and across processes: path.tmp.<pid>.<counter>.
std::filesystem::path temporary_name(const std::filesystem::path& path) {
  static std::atomic<unsigned long> counter{0};
  return path.string() + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}
}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path temporary = temporary_name(path);
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) throw Error(path.string() + ": cannot open a temporary file for writing in its folder");
      write(out);
      out.flush();
      if (!out) throw Error(path.string() + ": writing failed (disk full or file system error?)");
    }
    std::error_code code;
    std::filesystem::rename(temporary, path, code);
    if (code) throw Error(path.string() + ": cannot rename the finished temporary file: " + code.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

}  // namespace contactbench
