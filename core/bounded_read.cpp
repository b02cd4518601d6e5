#include "contactbench/core/bounded_read.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <system_error>
#include <vector>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace fs = std::filesystem;

namespace {

std::string describe_bytes(std::uintmax_t bytes) {
  const double gib = static_cast<double>(bytes) / static_cast<double>(std::uintmax_t{1} << 30);
  return std::to_string(bytes) + " bytes (" + std::to_string(gib).substr(0, 6) + " GiB)";
}

}  // namespace

namespace {

// The checks of read_file_bounded, then at most `head` of the file's bytes.
std::string read_bounded(const fs::path& path, std::uintmax_t max_bytes, const std::string& what,
                         std::uintmax_t head) {
  std::error_code code;
  const fs::file_status status = fs::status(path, code);  // follows links: a link to a file is fine
  switch (status.type()) {
    case fs::file_type::regular:
      break;
    case fs::file_type::not_found:
      throw InputError(path, 0, "no such file");
    case fs::file_type::directory:
      throw InputError(path, 0, "is a folder, not a file");
    case fs::file_type::character:
    case fs::file_type::block:
      throw InputError(path, 0, "is a device, not a file: " + what + " are read from files");
    case fs::file_type::fifo:
    case fs::file_type::socket:
      throw InputError(path, 0, "is a pipe or socket, not a file: " + what + " are read from files");
    default:
      throw InputError(path, 0, "cannot be inspected: " + (code ? code.message() : "unknown type"));
  }
  const std::uintmax_t size = fs::file_size(path, code);
  if (!code && size > max_bytes)
    throw InputError(path, 0,
                     "is " + describe_bytes(size) + ", more than the " + describe_bytes(max_bytes) +
                         " accepted for " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open the file for reading");
  // Straight into a string of the file's size (one read, no copies of a growing string), then in chunks for
  // whatever follows: a file that grows while it is read, or one whose size is reported as 0 (as /proc's
  // are).
  std::string content(code ? 0 : static_cast<std::size_t>(std::min(size, head)), '\0');
  in.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(in.gcount()));
  std::vector<char> buffer(1 << 16);
  while (in && content.size() < head) {
    in.read(buffer.data(),
            static_cast<std::streamsize>(std::min<std::uintmax_t>(buffer.size(), head - content.size())));
    content.append(buffer.data(), static_cast<std::size_t>(in.gcount()));
    // A file that grows while it is read (or reports a wrong size, as /proc does) is still bounded.
    if (content.size() > max_bytes)
      throw InputError(path, 0, "holds more than the " + describe_bytes(max_bytes) + " accepted for " + what);
  }
  if (in.bad()) throw InputError(path, 0, "reading the file failed");
  return content;
}

}  // namespace

std::string read_file_bounded(const fs::path& path, std::uintmax_t max_bytes, const std::string& what) {
  return read_bounded(path, max_bytes, what, std::numeric_limits<std::uintmax_t>::max());
}

std::string read_file_head(const fs::path& path, std::uintmax_t max_bytes, const std::string& what,
                           std::uintmax_t head_bytes) {
  return read_bounded(path, max_bytes, what, head_bytes);
}

}  // namespace contactbench
