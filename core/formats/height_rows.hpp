// The data block of a text topography (internal to core/formats/): every line a row of heights, the same
// count on every row and the counts a header promised, made into a surface.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/formats/raw_topography.hpp"
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

// How the rows are written. The project's own format states every height, so NaN and Inf there are refused;
// the other text formats (which go through channels, docs/formats.md "invalid points") mark invalid points
// with them.
struct RowSyntax {
  char separator = ' ';        // ' ': blanks (spaces, tabs); ',' or ';': that character, blanks around it
  bool decimal_comma = false;  // "1,5" is 1.5 (semicolon-separated files of locales that write so)
  bool non_finite_invalid = false;
};

// The rows of a text format with a header (interferometer, Gwyddion): blank-separated, NaN and Inf invalid.
RowSyntax header_text_syntax();

// The separator of a matrix or point list, from its first line: ';' if it has one, else ',' if it has one,
// else blanks; with ';' a comma inside a value is a decimal comma.
RowSyntax matrix_syntax(std::string_view first_line);

// Parses every line as a row of heights times `scale`: same count on every row, and the header's counts if it
// gave any. `context` ends the message for an empty block (" after the header"). With the header's counts and
// threads > 1 the rows are parsed on that many threads; the values and any message are the same.
DataBlock parse_data(const std::filesystem::path& path, std::span<const Line> lines, Real scale,
                     const std::optional<PromisedShape>& promised, std::string_view context,
                     const RowSyntax& syntax = {}, int threads = 1);

Surface make_surface(DataBlock block, Real lx, Real ly, bool periodic);

// A file's one channel, "height", of the block's heights in metres, with the sizes the file states (none: the
// caller gives them); `unit` names the file's own unit in messages.
RawTopography single_height_channel(DataBlock block, std::string unit, std::optional<Real> lx,
                                    std::optional<Real> ly);

}  // namespace contactbench::formats
