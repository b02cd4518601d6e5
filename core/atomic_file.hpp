// Write a file so that readers never see it half-written: write a temporary beside it, then rename.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>

namespace contactbench {

// Throws Error unless `path` may be replaced by a regular file: it must not exist, or be a regular file. A
// symbolic link, a device node (/dev/null, /dev/full), a pipe, a socket or a folder is refused with what it
// is, so that renaming a finished temporary over it can never swap out a device or a link's target.
void check_replaceable_file(const std::filesystem::path& path);

// Calls write(stream) on a temporary file in the target's folder, flushes it, and renames it over `path`
// (after check_replaceable_file). On any failure (the callback throws, the disk is full) the temporary is
// removed and Error is thrown; `path` then still holds whatever it held before.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write);

}  // namespace contactbench
