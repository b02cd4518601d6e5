// The memory a file's declared grid will take, checked before anything of that size is allocated or inflated
// (internal to core/formats/): a header may declare far more points than its bytes hold (a zip inflates them,
// a corrupt count asks for them), and the read must be refused at once, with the budget message `generate`
// gives, rather than grow until the kernel kills it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "contactbench/core/formats/raw_topography.hpp"

namespace contactbench::formats {

// Bytes per point a read holds at its peak besides the file's own bytes: the channel's values, the height map
// made of them, the surface's copy, and the centred (or levelled) copy a scene makes, 8 B each.
inline constexpr std::uintmax_t kReadBytesPerPoint = 32;

// Throws InputError naming the file when nx * ny points, at kReadBytesPerPoint plus `file_bytes_per_point`
// (what a reader must inflate or copy per point before decoding), do not fit in the available memory.
void check_declared_memory(const std::filesystem::path& path, Index nx, Index ny,
                           std::uintmax_t file_bytes_per_point, const std::string& what);

// The check, then channel.values sized to channel.nx * channel.ny (zeros).
void allocate_values(const std::filesystem::path& path, Channel& channel,
                     std::uintmax_t file_bytes_per_point = 0);

}  // namespace contactbench::formats
