// Writing the project's text format (docs/formats.md "The text formats"): read_project returns the same
// doubles.
#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <string>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_values.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

// Appends one row of heights, blank-separated, each in its shortest round-trip form.
void append_row(std::string& text, const HeightMap& heights, Index row) {
  std::array<char, 32> buffer{};
  for (Index column = 0; column < heights.cols(); ++column) {
    if (column > 0) text += ' ';
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), heights(row, column));
    text.append(buffer.data(), result.ptr);
  }
  text += '\n';
}

}  // namespace

namespace {

// The header and rows; `quantity` empty for heights (the header then has no quantity key).
void write_values(const std::filesystem::path& path, const Surface& surface, const std::string& quantity,
                  const std::string& unit) {
  const Grid& grid = surface.grid();
  const std::string header = std::string(formats::project_magic) + "\n# nx=" + std::to_string(grid.nx) +
                             " ny=" + std::to_string(grid.ny) + " lx=" + formats::format_real(grid.lx) +
                             " ly=" + formats::format_real(grid.ly) +
                             " periodic=" + (grid.periodic ? "true" : "false") +
                             (quantity.empty() ? "" : " quantity=" + quantity) + " unit=" + unit + "\n";
  write_file_atomically(path, [&](std::ostream& out) {
    out.write(header.data(), static_cast<std::streamsize>(header.size()));
    // Row by row: a large surface never needs its whole text in memory.
    std::string row_text;
    for (Index row = 0; row < grid.ny; ++row) {
      row_text.clear();
      append_row(row_text, surface.heights(), row);
      out.write(row_text.data(), static_cast<std::streamsize>(row_text.size()));
    }
  });
}

// A header value is one token of letters, digits and underscores (the reader splits at blanks and '=').
void check_token(const std::string& what, const std::string& value) {
  const bool plain = !value.empty() && std::all_of(value.begin(), value.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '*' || c == '/';
  });
  if (!plain) throw Error("write_field: the " + what + " '" + value + "' is not one plain word");
}

}  // namespace

void write_surface(const std::filesystem::path& path, const Surface& surface) {
  write_values(path, surface, "", "m");
}

void write_field(const std::filesystem::path& path, const Field& field) {
  check_token("quantity", field.quantity);
  check_token("unit", field.unit);
  write_values(path, field.values, field.quantity, field.unit);
}

}  // namespace contactbench
