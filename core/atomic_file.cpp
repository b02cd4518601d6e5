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

const char* kind_of(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::symlink:
      return "a symbolic link";
    case std::filesystem::file_type::directory:
      return "a folder";
    case std::filesystem::file_type::character:
      return "a character device";
    case std::filesystem::file_type::block:
      return "a block device";
    case std::filesystem::file_type::fifo:
      return "a named pipe";
    case std::filesystem::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}
}  // namespace

void check_replaceable_file(const std::filesystem::path& path) {
  if (path.empty()) throw Error("the output file name is empty");
  std::error_code code;
  const std::filesystem::file_status status = std::filesystem::symlink_status(path, code);
  if (code && code != std::errc::no_such_file_or_directory)
    throw Error(path.string() + ": cannot inspect the output path: " + code.message());
  const std::filesystem::file_type type = status.type();
  if (type == std::filesystem::file_type::not_found || type == std::filesystem::file_type::regular) return;
  throw Error(path.string() + ": is " + kind_of(type) +
              "; refusing to replace it with the output (name a regular file, new or old)");
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  check_replaceable_file(path);
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
