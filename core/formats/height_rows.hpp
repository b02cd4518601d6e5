// The data block of a text topography (internal to core/formats/): every line a row of heights, the same
// count on every row and the counts a header promised, made into a surface.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench::formats {

// Row and column counts a header promises, with how to name them in a message.
struct PromisedShape {
  Index rows = 0;
  Index cols = 0;
  std::string rows_name;  // e.g. "h=305 (line 1)"
  std::string cols_name;
  long rows_line = 0;
};

// Heights in row-major order (rows along y) as parsed from the data block.
struct DataBlock {
  std::vector<Real> values;
  Index rows = 0;
  Index cols = 0;
};

// Parses every line as a row of heights times `scale`: same count on every row, and the header's counts if it
// gave any. `context` ends the message for an empty block (" after the header").
DataBlock parse_data(const std::filesystem::path& path, std::span<const Line> lines, Real scale,
                     const std::optional<PromisedShape>& promised, std::string_view context);

Surface make_surface(DataBlock block, Real lx, Real ly, bool periodic);

}  // namespace contactbench::formats
