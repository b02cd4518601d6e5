#include "contactbench/core/formats/height_rows.hpp"

#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <system_error>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// One height token times the unit scale; throws naming the line for anything that is not a number, and for
// NaN or Inf unless they mark invalid points.
Real parse_height(const fs::path& path, long line, std::string_view written, Real scale,
                  const RowSyntax& syntax) {
  std::string decimal_point;
  std::string_view token = written;
  if (syntax.decimal_comma && token.find(',') != std::string_view::npos) {
    decimal_point = std::string(token);
    for (char& c : decimal_point)
      if (c == ',') c = '.';
    token = decimal_point;
  }
  if (token.empty()) throw InputError(path, line, "an empty value between two separators");
  Real value = 0;
  const char* last = token.data() + token.size();
  const auto [end, error] = parse_real_prefix(token.data(), last, value);
  if (error == std::errc::result_out_of_range && end == last)
    throw InputError(path, line, quoted(written) + " is out of the range of a double");
  if (error != std::errc() || end != last) throw InputError(path, line, quoted(written) + " is not a number");
  if (!std::isfinite(value)) {
    if (syntax.non_finite_invalid) return std::numeric_limits<Real>::quiet_NaN();
    throw InputError(path, line, quoted(written) + " is not finite (NaN or Inf)");
  }
  const Real height = value * scale;
  if (!std::isfinite(height))
    throw InputError(path, line,
                     quoted(token) + " times the height factor " + format_real(scale) + " is not finite");
  return height;
}

// The values of one row: split at blanks, or at the separator with the blanks around each value dropped (an
// empty value between two separators is refused by parse_height).
template <typename Visit>
void for_each_value(std::string_view text, const RowSyntax& syntax, Visit&& visit) {
  if (syntax.separator == ' ') return for_each_token(text, is_blank, visit);
  std::size_t start = 0;
  while (true) {
    const std::size_t end = text.find(syntax.separator, start);
    visit(trim(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start),
               is_blank));
    if (end == std::string_view::npos) return;
    start = end + 1;
  }
}

// The rows of a block whose header promised its counts, parsed on `threads` threads, each row into its own
// place; nothing if any row is defective (wrong count, a bad token), for the serial pass to name the first
// defect as it always has.
std::optional<DataBlock> parse_rows_in_parallel(const fs::path& path, std::span<const Line> lines, Real scale,
                                                const PromisedShape& promised, const RowSyntax& syntax,
                                                int threads) {
  const auto rows = static_cast<std::ptrdiff_t>(lines.size());
  const auto cols = static_cast<std::size_t>(promised.cols);
  DataBlock block;
  block.rows = promised.rows;
  block.cols = promised.cols;
  block.values.resize(static_cast<std::size_t>(rows) * cols);
  std::atomic<bool> defect = false;
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::ptrdiff_t row = 0; row < rows; ++row) {
    if (defect.load(std::memory_order_relaxed)) continue;
    const Line& line = lines[static_cast<std::size_t>(row)];
    Real* const out = block.values.data() + static_cast<std::size_t>(row) * cols;
    std::size_t count = 0;
    try {  // an exception must not leave a parallel region
      for_each_value(line.text, syntax, [&](std::string_view token) {
        if (count < cols) out[count] = parse_height(path, line.number, token, scale, syntax);
        ++count;
      });
    } catch (...) {
      defect = true;
    }
    if (count != cols) defect = true;
  }
  if (defect) return std::nullopt;
  return block;
}

}  // namespace

RowSyntax header_text_syntax() {
  RowSyntax syntax;
  syntax.non_finite_invalid = true;
  return syntax;
}

RowSyntax matrix_syntax(std::string_view first_line) {
  RowSyntax syntax;
  syntax.non_finite_invalid = true;
  if (first_line.find(';') != std::string_view::npos) {
    syntax.separator = ';';
    syntax.decimal_comma = true;
  } else if (first_line.find(',') != std::string_view::npos) {
    syntax.separator = ',';
  }
  return syntax;
}

DataBlock parse_data(const fs::path& path, std::span<const Line> lines, Real scale,
                     const std::optional<PromisedShape>& promised, std::string_view context,
                     const RowSyntax& syntax, int threads) {
  if (lines.empty()) throw InputError(path, 0, "no data rows" + std::string(context));
  // What the text can hold (a line of L characters holds at most (L + 1) / 2 values): no more is allocated,
  // so that a header's wrong promise costs no memory.
  std::size_t most_values = 0;
  for (const Line& line : lines)
    most_values += (line.text.size() + 1) / 2;
  if (threads > 1 && promised && static_cast<Index>(lines.size()) == promised->rows &&
      static_cast<std::size_t>(promised->cols) <= most_values / lines.size())
    if (std::optional<DataBlock> block =
            parse_rows_in_parallel(path, lines, scale, *promised, syntax, threads))
      return std::move(*block);
  DataBlock block;
  // Room for every value at once, so that a large block is not copied as it grows: the header's counts, else
  // the first row's count times the rows, never more than the text can hold.
  const auto reserve = [&](std::size_t rows, std::size_t cols) {
    if (cols > 0) block.values.reserve(rows > most_values / cols ? most_values : rows * cols);
  };
  if (promised) reserve(static_cast<std::size_t>(promised->rows), static_cast<std::size_t>(promised->cols));
  long first_row_line = 0;
  for (const Line& line : lines) {
    if (promised && block.rows == promised->rows)
      throw InputError(path, line.number, "more data rows than the header's " + promised->rows_name);
    const std::size_t before = block.values.size();
    for_each_value(line.text, syntax, [&](std::string_view token) {
      block.values.push_back(parse_height(path, line.number, token, scale, syntax));
    });
    const auto count = static_cast<Index>(block.values.size() - before);
    if (promised && count != promised->cols)
      throw InputError(path, line.number,
                       "row has " + std::to_string(count) + " values but the header's " +
                           promised->cols_name + " says " + std::to_string(promised->cols));
    if (block.rows == 0) {
      block.cols = count;
      first_row_line = line.number;
      if (!promised && count > 0) reserve(lines.size(), static_cast<std::size_t>(count));
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

RawTopography single_height_channel(DataBlock block, std::string unit, std::optional<Real> lx,
                                    std::optional<Real> ly) {
  Channel channel = make_channel("height", true, std::move(unit), block.cols, block.rows);
  channel.values = std::move(block.values);
  channel.lx = lx;
  channel.ly = ly;
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats
