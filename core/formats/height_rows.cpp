#include "contactbench/core/formats/height_rows.hpp"

#include <cmath>
#include <system_error>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// One height token times the unit scale; throws naming the line for anything that is not a finite number.
Real parse_height(const fs::path& path, long line, std::string_view token, Real scale) {
  Real value = 0;
  const char* last = token.data() + token.size();
  const auto [end, error] = parse_real_prefix(token.data(), last, value);
  if (error == std::errc::result_out_of_range && end == last)
    throw InputError(path, line, quoted(token) + " is out of the range of a double");
  if (error != std::errc() || end != last) throw InputError(path, line, quoted(token) + " is not a number");
  if (!std::isfinite(value)) throw InputError(path, line, quoted(token) + " is not finite (NaN or Inf)");
  const Real height = value * scale;
  if (!std::isfinite(height))
    throw InputError(path, line,
                     quoted(token) + " times the height factor " + format_real(scale) + " is not finite");
  return height;
}

}  // namespace

DataBlock parse_data(const fs::path& path, std::span<const Line> lines, Real scale,
                     const std::optional<PromisedShape>& promised, std::string_view context) {
  if (lines.empty()) throw InputError(path, 0, "no data rows" + std::string(context));
  DataBlock block;
  long first_row_line = 0;
  for (const Line& line : lines) {
    if (promised && block.rows == promised->rows)
      throw InputError(path, line.number, "more data rows than the header's " + promised->rows_name);
    const std::size_t before = block.values.size();
    for_each_token(line.text, is_blank, [&](std::string_view token) {
      block.values.push_back(parse_height(path, line.number, token, scale));
    });
    const auto count = static_cast<Index>(block.values.size() - before);
    if (promised && count != promised->cols)
      throw InputError(path, line.number,
                       "row has " + std::to_string(count) + " values but the header's " +
                           promised->cols_name + " says " + std::to_string(promised->cols));
    if (block.rows == 0) {
      block.cols = count;
      first_row_line = line.number;
    } else if (count != block.cols) {
      throw InputError(path, line.number,
                       "ragged row: " + std::to_string(count) + " values, but the first data row (line " +
                           std::to_string(first_row_line) + ") has " + std::to_string(block.cols));
    }
    ++block.rows;
  }
  if (promised && block.rows != promised->rows)
    throw InputError(path, promised->rows_line,
                     "the header's " + promised->rows_name + " promises " + std::to_string(promised->rows) +
                         " rows but the file has " + std::to_string(block.rows) + " data rows");
  return block;
}

Surface make_surface(DataBlock block, Real lx, Real ly, bool periodic) {
  const Grid grid{block.cols, block.rows, lx, ly, periodic};
  HeightMap heights = Eigen::Map<const HeightMap>(block.values.data(), block.rows, block.cols);
  return Surface(grid, std::move(heights));
}

}  // namespace contactbench::formats
