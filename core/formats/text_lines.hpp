// The lines of a text topography (internal to core/formats/): numbered, trimmed, the blank ones dropped, and
// the check that the bytes are text at all.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace contactbench::formats {

// One non-blank line of a file: its text without line end and outer blanks, and its 1-based number.
struct Line {
  std::string_view text;
  long number = 0;
};

// Splits at LF, CRLF or a lone CR, numbering lines from 1, and keeps the non-blank ones.
std::vector<Line> non_blank_lines(std::string_view content);

// "line 3" or "lines 1-4", for messages naming a header.
std::string line_range(std::span<const Line> lines);

// Text formats only: UTF-16 text and binary bytes are named as such before any parsing (their first token
// would otherwise be reported as "not a number", or as a matrix without a size).
void check_is_text(const std::filesystem::path& path, std::string_view bytes);

}  // namespace contactbench::formats
