// A plain matrix, docs/formats.md "The text formats": blank-separated heights in metres, rows along y, no
// header; the lateral size comes from the caller (square pixels unless it gives both).
#include <optional>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/lateral_sizes.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace fs = std::filesystem;

Surface read_plain_matrix(const fs::path& path, std::span<const Line> lines,
                          const TopographyReadOptions& options) {
  if (!options.lx)
    throw InputError(path, 0, "no lateral size: a plain matrix needs the caller's size (--size)");
  check_lateral_size(path, 0, "the given lx", *options.lx);
  if (options.ly) check_lateral_size(path, 0, "the given ly", *options.ly);
  DataBlock block = parse_data(path, lines, 1.0, std::nullopt, "");
  // Square pixels unless told otherwise: ly / ny = lx / nx.
  const Real ly =
      options.ly.value_or(*options.lx * static_cast<Real>(block.rows) / static_cast<Real>(block.cols));
  check_lateral_size(path, 0, "ly (square pixels from the given lx)", ly);
  return make_surface(std::move(block), *options.lx, ly, options.periodic.value_or(false));
}

}  // namespace contactbench::formats
