#include "contactbench/core/formats/line_scan.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "contactbench/core/bounded_read.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/height_unit.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

bool is_separator(char c) {
  return c == ',' || is_blank(c);
}

// The values of a data line: comma- or blank-separated; Dektak ends each line with empty fields (",,").
std::vector<std::string_view> fields(std::string_view text) {
  return split_tokens(text, is_separator);
}

// The column names of a header line: comma-separated (then trimmed), or blank-separated without a comma.
std::vector<std::string_view> header_names(std::string_view text) {
  if (text.find(',') == std::string_view::npos) return split_tokens(text, is_blank);
  std::vector<std::string_view> names;
  for (std::string_view name : split_tokens(text, [](char c) { return c == ','; }))
    if (!(name = trim(name, is_blank)).empty()) names.push_back(name);
  return names;
}

std::optional<std::pair<Real, Real>> point(std::string_view text) {
  const std::vector<std::string_view> values = fields(text);
  if (values.size() != 2) return std::nullopt;
  const std::optional<Real> x = parse_real(values[0]), h = parse_real(values[1]);
  if (!x || !h) return std::nullopt;
  return std::pair{*x, *h};
}

// Where the data lines start: after Dektak's "Scan Data" and its column line, after a one-line header, or at
// the top; npos when the lines are not a line scan.
std::size_t data_start(std::span<const Line> lines) {
  for (std::size_t k = 0; k + 1 < lines.size(); ++k)
    if (lines[k].text == "Scan Data" && lines[k + 1].text.starts_with("Lateral")) return k + 2;
  if (lines.empty()) return std::string_view::npos;
  const bool header = !point(lines.front().text) && header_names(lines.front().text).size() == 2;
  const std::size_t start = header ? 1 : 0;
  // Without a header, at least eight points: a short two-column file is more likely a matrix.
  if (lines.size() < start + (header ? 3 : 8)) return std::string_view::npos;
  // Every line two numbers, x strictly increasing (checked on the first lines only: cheap; the reader checks
  // them all).
  std::optional<Real> previous;
  for (std::size_t k = start; k < std::min(lines.size(), start + 64); ++k) {
    const auto p = point(lines[k].text);
    if (!p || !std::isfinite(p->first) || !std::isfinite(p->second) || (previous && !(p->first > *previous)))
      return std::string_view::npos;
    previous = p->first;
  }
  return start;
}

// Metres per unit named in a column header ("Lateral um", "Raw Micrometer", "X_(microns)"), if any.
std::optional<Real> unit_in_header(std::string_view header, std::string& name) {
  for (const auto& [word, metres, unit] :
       {std::tuple{"Micrometer", 1e-6, "um"}, std::tuple{"micron", 1e-6, "um"}, std::tuple{" um", 1e-6, "um"},
        std::tuple{"(um)", 1e-6, "um"}, std::tuple{"Nanometer", 1e-9, "nm"}, std::tuple{" nm", 1e-9, "nm"},
        std::tuple{"(nm)", 1e-9, "nm"}, std::tuple{"Millimeter", 1e-3, "mm"}, std::tuple{" mm", 1e-3, "mm"}})
    if (header.find(word) != std::string_view::npos) {
      name = unit;
      return metres;
    }
  return std::nullopt;
}

}  // namespace

bool looks_like_line_scan(std::span<const Line> lines) {
  return data_start(lines) != std::string_view::npos;
}

LineScan read_line_scan(const fs::path& path, const TopographyReadOptions& options) {
  const std::string content = read_file_bounded(path, kMaxTopographyFileBytes, "topographies");
  const std::vector<Line> lines = non_blank_lines(content);
  const std::size_t start = data_start(lines);
  if (start == std::string_view::npos)
    throw InputError(path, 0, "not a line scan: expected lines of two numbers, x strictly increasing");
  LineScan scan;
  scan.source = start >= 2 && lines[start - 2].text == "Scan Data" ? "dektak" : "x h text";
  // The columns' units where a header names them; else the caller's unit; else metres (checked below).
  std::string x_name, h_name;
  std::optional<Real> x_unit, h_unit;
  if (start > 0) {
    const std::vector<std::string_view> names = header_names(lines[start - 1].text);
    if (!names.empty()) x_unit = unit_in_header(names[0], x_name);
    if (names.size() > 1) h_unit = unit_in_header(names[1], h_name);
  }
  if (options.unit && h_unit)
    throw InputError(path, lines[start - 1].number,
                     "the column header states the heights' unit ('" + h_name +
                         "'); a unit (--unit) is only for files that state none");
  const Real given = options.unit ? 1.0 / given_units_per_metre(path, *options.unit) : 1.0;
  for (std::size_t k = start; k < lines.size(); ++k) {
    const auto p = point(lines[k].text);
    if (!p)
      throw InputError(path, lines[k].number,
                       "a line scan's data line holds two numbers (x and h), got " + quoted(lines[k].text));
    if (!std::isfinite(p->first) || !std::isfinite(p->second))
      throw InputError(path, lines[k].number, "x and h must be finite, got " + quoted(lines[k].text));
    const Real x = p->first * x_unit.value_or(given);
    if (!scan.x.empty() && !(x > scan.x.back()))
      throw InputError(path, lines[k].number, "x must increase strictly along a line scan");
    scan.x.push_back(x);
    scan.heights.push_back(p->second * h_unit.value_or(given));
  }
  scan.unit = h_unit ? h_name : options.unit.value_or("m");
  if (!h_unit && !options.unit) check_plausible_as_metres(path, scan.heights, "line scan");
  return scan;
}

}  // namespace contactbench::formats
