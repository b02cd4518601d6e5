// Writing the project's text format (docs/formats.md "The text formats"): read_project returns the same
// doubles.
#include <array>
#include <charconv>
#include <string>

#include "contactbench/core/atomic_file.hpp"
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

void write_surface(const std::filesystem::path& path, const Surface& surface) {
  const Grid& grid = surface.grid();
  const std::string header = std::string(formats::project_magic) + "\n# nx=" + std::to_string(grid.nx) +
                             " ny=" + std::to_string(grid.ny) + " lx=" + formats::format_real(grid.lx) +
                             " ly=" + formats::format_real(grid.ly) +
                             " periodic=" + (grid.periodic ? "true" : "false") + " unit=m\n";
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

}  // namespace contactbench
