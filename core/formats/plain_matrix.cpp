// A plain matrix, docs/formats.md "The text formats": heights separated by blanks, commas or semicolons
// (then a comma in a value is a decimal comma), rows along y, no header and no unit; NaN and Inf mark invalid
// points. The lateral size comes from the caller (square pixels unless it gives both), through the channels
// like a NumPy array.
#include <string>
#include <utility>

#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/text_readers.hpp"

namespace contactbench::formats {

RawTopography read_plain_matrix(const std::filesystem::path& path, std::span<const Line> lines) {
  DataBlock block = parse_data(path, lines, 1.0, std::nullopt, "", matrix_syntax(lines.front().text));
  return single_height_channel(std::move(block), "", std::nullopt, std::nullopt);
}

}  // namespace contactbench::formats
