// Reading a whole input file with a bound: only regular files (a device such as /dev/zero, a pipe or a folder
// is refused by name, never read without end), and never more than a stated number of bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace contactbench {

// Largest topography file read [bytes]: 16 GiB, about a 25,000 x 25,000 text export or a 45,000^2 float64
// binary; larger inputs are refused with their size, before anything is allocated.
inline constexpr std::uintmax_t kMaxTopographyFileBytes = std::uintmax_t{16} << 30;

// The file's bytes. Throws InputError (path, line 0) when it does not exist, is not a regular file (says what
// it is), is larger than max_bytes (says both sizes, and what the bound is for: `what`), or cannot be read.
std::string read_file_bounded(const std::filesystem::path& path, std::uintmax_t max_bytes,
                              const std::string& what);

// The same checks (the whole file's size included), then only the first head_bytes bytes (all of a smaller
// file): for what a file's beginning decides, such as its format.
std::string read_file_head(const std::filesystem::path& path, std::uintmax_t max_bytes,
                           const std::string& what, std::uintmax_t head_bytes);

}  // namespace contactbench
