// An x y z point list, docs/formats.md "The text formats": one point a line (separated as a plain matrix
// is), no unit, on a regular grid: the distinct x and the distinct y are evenly spaced and every (x, y) is
// listed once, in any order. An irregular list (scattered points, uneven steps, a point missing or given
// twice) is refused, saying so: interpolating it would invent a surface. Lateral size = count x step, as
// for the other gridded formats.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/detection.hpp"
#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// Coordinates written as text carry about 7 significant digits; a coordinate off its grid line by more than
// this fraction of the step is not on a regular grid.
constexpr Real grid_tolerance = 1e-3;

std::vector<Real> distinct(std::vector<Real> values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  return values;
}

// The coordinates of the first three columns, or nothing when a line is not three finite numbers.
std::optional<std::pair<std::vector<Real>, std::vector<Real>>> coordinates(std::span<const Line> lines) {
  std::vector<Real> xs, ys;
  const RowSyntax syntax = matrix_syntax(lines.front().text);
  for (const Line& line : lines) {
    std::vector<std::string_view> tokens;
    if (syntax.separator == ' ') {
      tokens = split_tokens(line.text, is_blank);
    } else {
      tokens = split_tokens(line.text, [&](char c) { return c == syntax.separator; });
      for (std::string_view& token : tokens)
        token = trim(token, is_blank);
    }
    if (tokens.size() != 3) return std::nullopt;
    const std::optional<Real> x = parse_real(tokens[0]), y = parse_real(tokens[1]);
    if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y)) return std::nullopt;
    xs.push_back(*x);
    ys.push_back(*y);
  }
  return std::pair{std::move(xs), std::move(ys)};
}

// The grid step of evenly spaced distinct values; InputError naming the axis when they are not.
Real even_step(const fs::path& path, const std::vector<Real>& grid, const char* axis) {
  if (grid.size() < 2)
    throw InputError(
        path, 0,
        std::string("the point list has a single ") + axis + " value: a line of points is not a surface");
  const Real step = (grid.back() - grid.front()) / static_cast<Real>(grid.size() - 1);
  for (std::size_t k = 0; k < grid.size(); ++k) {
    const Real expected = grid.front() + step * static_cast<Real>(k);
    if (!(std::abs(grid[k] - expected) <= grid_tolerance * step))
      throw InputError(path, 0,
                       std::string("irregular point list: the ") + axis + " values are not evenly spaced (" +
                           format_real(grid[k]) + " where the step " + format_real(step) + " puts " +
                           format_real(expected) +
                           "); only x y z lists on a regular grid are read, scattered points are not "
                           "interpolated");
  }
  return step;
}

}  // namespace

bool looks_like_point_list(const fs::path& path, std::span<const Line> lines) {
  if (lines.empty()) return false;
  if (lower_extension(path) == ".xyz") return true;
  if (lines.size() < 4) return false;
  // Cheap first: a matrix of another width is not looked at further.
  const RowSyntax syntax = matrix_syntax(lines.front().text);
  const std::size_t columns =
      syntax.separator == ' '
          ? split_tokens(lines.front().text, is_blank).size()
          : split_tokens(lines.front().text, [&](char c) { return c == syntax.separator; }).size();
  if (columns != 3) return false;
  const auto xy = coordinates(lines);
  if (!xy) return false;
  const std::size_t nx = distinct(xy->first).size(), ny = distinct(xy->second).size();
  return nx >= 2 && ny >= 2 && nx * ny == lines.size();
}

RawTopography read_xyz_points(const fs::path& path, std::span<const Line> lines) {
  const DataBlock block = parse_data(path, lines, 1.0, std::nullopt, "", matrix_syntax(lines.front().text));
  if (block.cols != 3)
    throw InputError(
        path, lines.front().number,
        "a point list needs three values a line (x y z), this one has " + std::to_string(block.cols));
  std::vector<Real> xs, ys;
  for (Index k = 0; k < block.rows; ++k) {
    const Real x = block.values[static_cast<std::size_t>(3 * k)],
               y = block.values[static_cast<std::size_t>(3 * k + 1)];
    if (!std::isfinite(x) || !std::isfinite(y))
      throw InputError(path, lines[static_cast<std::size_t>(k)].number,
                       "a point's x and y must be finite numbers (only z may be NaN, an invalid point)");
    xs.push_back(x);
    ys.push_back(y);
  }
  const std::vector<Real> grid_x = distinct(xs), grid_y = distinct(ys);
  const Real dx = even_step(path, grid_x, "x"), dy = even_step(path, grid_y, "y");
  const auto nx = static_cast<Index>(grid_x.size()), ny = static_cast<Index>(grid_y.size());
  if (nx * ny != block.rows)
    throw InputError(path, 0,
                     "irregular point list: " + std::to_string(block.rows) + " points on " +
                         std::to_string(nx) + " x values and " + std::to_string(ny) +
                         " y values (a full grid has " + std::to_string(nx * ny) +
                         "); only x y z lists on a regular grid are read");
  Channel channel = make_channel("height", true, "", nx, ny);
  channel.lx = dx * static_cast<Real>(nx);
  channel.ly = dy * static_cast<Real>(ny);
  // Each grid point once: a point given twice leaves another unset (marked until it is written).
  std::vector<bool> seen(static_cast<std::size_t>(nx * ny), false);
  channel.values.assign(static_cast<std::size_t>(nx * ny), 0.0);
  for (Index k = 0; k < block.rows; ++k) {
    const auto ix = static_cast<Index>(std::llround((xs[static_cast<std::size_t>(k)] - grid_x.front()) / dx));
    const auto iy = static_cast<Index>(std::llround((ys[static_cast<std::size_t>(k)] - grid_y.front()) / dy));
    const auto at = static_cast<std::size_t>(iy * nx + ix);
    if (seen[at])
      throw InputError(path, lines[static_cast<std::size_t>(k)].number,
                       "irregular point list: the point (" + format_real(xs[static_cast<std::size_t>(k)]) +
                           ", " + format_real(ys[static_cast<std::size_t>(k)]) + ") is listed twice");
    seen[at] = true;
    channel.values[at] = block.values[static_cast<std::size_t>(3 * k + 2)];
  }
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats
