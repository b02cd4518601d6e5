// Gwyddion's text export (docs/formats.md "The text formats"): '#' header lines "# Channel: ...",
// "# Width: L UNIT", "# Height: L UNIT", "# Value units: UNIT" (keys in any capitals), then the rows; NaN and
// Inf mark invalid points (Gwyddion writes masked or unmeasured points so), handled by the channels.
#include <optional>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/lateral_sizes.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace fs = std::filesystem;

RawTopography read_gwyddion(const fs::path& path, std::span<const Line> lines,
                            const TopographyReadOptions& options) {
  std::size_t header_size = 0;
  while (header_size < lines.size() && lines[header_size].text.starts_with('#'))
    ++header_size;
  const std::span<const Line> header = lines.first(header_size);

  HeaderEntry width, height, value_units;
  for (const Line& line : header) {
    const std::string_view body = line.text.substr(1);
    const std::size_t colon = body.find(':');
    if (colon == std::string_view::npos) continue;  // a comment, not a key
    const std::string_view key = trim(body.substr(0, colon), is_blank);
    const std::string_view value = trim(body.substr(colon + 1), is_blank);
    HeaderEntry* entry = equals_ignoring_case(key, "Width")         ? &width
                         : equals_ignoring_case(key, "Height")      ? &height
                         : equals_ignoring_case(key, "Value units") ? &value_units
                                                                    : nullptr;
    if (entry != nullptr) store_entry(path, line, key, value, *entry);  // Channel and others: not needed
  }
  const long header_line = header.front().number;
  const std::string header_name = "Gwyddion header (" + line_range(header) + ")";
  for (const auto& [key, entry] :
       {std::pair{"Width", width}, std::pair{"Height", height}, std::pair{"Value units", value_units}})
    if (entry.line == 0)
      throw InputError(path, header_line, header_name + " has no '# " + key + ": ...' line");

  const Real lx = parse_size(path, width.line, "Width", width.value);
  const Real ly = parse_size(path, height.line, "Height", height.value);
  check_agrees(path, width.line, "lx", lx, options.lx);
  check_agrees(path, height.line, "ly", ly, options.ly);
  const Real scale = length_unit_or_throw(path, value_units.line, "Value units", value_units.value);

  DataBlock block = parse_data(path, lines.subspan(header_size), scale, std::nullopt,
                               " after the " + header_name, header_text_syntax());
  return single_height_channel(std::move(block), std::string(value_units.value), lx, ly);
}

}  // namespace contactbench::formats
