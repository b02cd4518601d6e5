// Write a file so that readers never see it half-written: write a temporary beside it, then rename.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace contactbench {

// Calls write(stream) on a temporary file in the target's folder, flushes it, and renames it over `path`.
// On any failure (the callback throws, the disk is full) the temporary is removed and Error is thrown;
// `path` then still holds whatever it held before.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace contactbench
