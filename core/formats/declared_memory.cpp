#include "contactbench/core/formats/declared_memory.hpp"

#include "contactbench/core/error.hpp"
#include "contactbench/core/memory_budget.hpp"

namespace contactbench::formats {

void check_declared_memory(const std::filesystem::path& path, Index nx, Index ny,
                           std::uintmax_t file_bytes_per_point, const std::string& what) {
  const std::uintmax_t points =
      saturating_product(static_cast<std::uintmax_t>(nx), static_cast<std::uintmax_t>(ny));
  try {
    check_fits_in_memory(
        saturating_product(points, saturating_sum(kReadBytesPerPoint, file_bytes_per_point)),
        "reading " + what + " of " + std::to_string(nx) + " x " + std::to_string(ny) + " points");
  } catch (const InputError&) {
    throw;
  } catch (const Error& error) {
    throw InputError(path, 0, error.what());
  }
}

void allocate_values(const std::filesystem::path& path, Channel& channel,
                     std::uintmax_t file_bytes_per_point) {
  check_declared_memory(path, channel.nx, channel.ny, file_bytes_per_point, "channel '" + channel.name + "'");
  channel.values.assign(static_cast<std::size_t>(channel.nx) * static_cast<std::size_t>(channel.ny), 0.0);
}

}  // namespace contactbench::formats
