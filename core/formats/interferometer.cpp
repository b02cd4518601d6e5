// An interferometer's text export (docs/formats.md "The text formats"): a header of key=value lines
// ("h=NY w=NX", "pixel size=... UNIT", "data unit=...", "height conversion factor (-> m)=...") then the rows.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/lateral_sizes.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view interferometer_factor_key = "height conversion factor (-> m)";

// "h=650 w=650" holds several key=value pairs; "pixel size=3.7e-7 m" is one key (with a blank) and its value.
std::vector<std::pair<std::string_view, std::string_view>> key_value_pairs(std::string_view text) {
  std::vector<std::pair<std::string_view, std::string_view>> pairs;
  const std::vector<std::string_view> tokens = split_tokens(text, is_blank);
  const bool all_pairs = std::all_of(tokens.begin(), tokens.end(),
                                     [](std::string_view token) { return token.find('=') != token.npos; });
  const auto split = [](std::string_view item) {
    const std::size_t equals = item.find('=');
    return std::pair{trim(item.substr(0, equals), is_blank), trim(item.substr(equals + 1), is_blank)};
  };
  if (all_pairs) {
    for (const std::string_view token : tokens)
      pairs.push_back(split(token));
  } else {
    pairs.push_back(split(text));
  }
  return pairs;
}

}  // namespace

RawTopography read_interferometer(const fs::path& path, std::span<const Line> lines,
                                  const TopographyReadOptions& options) {
  // The header is the leading run of key=value lines; data rows never contain '='.
  std::size_t header_size = 0;
  while (header_size < lines.size() && lines[header_size].text.find('=') != std::string_view::npos)
    ++header_size;
  const std::span<const Line> header = lines.first(header_size);

  HeaderEntry h, w, pixel_size, data_unit, factor;
  for (const Line& line : header)
    for (const auto& [key, value] : key_value_pairs(line.text)) {
      HeaderEntry* entry = key == "h"                         ? &h
                           : key == "w"                       ? &w
                           : key == "pixel size"              ? &pixel_size
                           : key == "data unit"               ? &data_unit
                           : key == interferometer_factor_key ? &factor
                                                              : nullptr;
      if (entry != nullptr) store_entry(path, line, key, value, *entry);  // other keys carry nothing we use
    }
  const long header_line = header.front().number;
  const std::string header_name = "interferometer header (" + line_range(header) + ")";
  if (h.line == 0) throw InputError(path, header_line, header_name + " has no 'h=<rows>' count");
  if (w.line == 0) throw InputError(path, header_line, header_name + " has no 'w=<columns>' count");
  if (pixel_size.line == 0)
    throw InputError(path, header_line, header_name + " has no 'pixel size=<value> <unit>' line");

  const Index rows = parse_count(path, h.line, "h", h.value);
  const Index columns = parse_count(path, w.line, "w", w.value);
  const Real pixel = parse_size(path, pixel_size.line, "pixel size", pixel_size.value);
  const Real lx = static_cast<Real>(columns) * pixel;
  const Real ly = static_cast<Real>(rows) * pixel;
  check_lateral_size(path, pixel_size.line, "lx (w times the pixel size)", lx);
  check_lateral_size(path, pixel_size.line, "ly (h times the pixel size)", ly);
  check_agrees(path, pixel_size.line, "lx", lx, options.lx);
  check_agrees(path, pixel_size.line, "ly", ly, options.ly);

  // The factor converts whatever the data unit is (rad, say) to metres; without it the data must be lengths.
  Real scale = 1;
  if (factor.line != 0) {
    const std::optional<Real> value = parse_real(factor.value);
    if (!value || !std::isfinite(*value) || *value == 0)
      throw InputError(path, factor.line,
                       std::string(interferometer_factor_key) + " must be a finite non-zero number, got " +
                           quoted(factor.value));
    scale = *value;
  } else if (data_unit.line != 0) {
    const std::optional<Real> metres = length_unit_in_metres(data_unit.value);
    if (!metres)
      throw InputError(path, data_unit.line,
                       "data unit " + quoted(data_unit.value) + " is not a length unit and there is no '" +
                           std::string(interferometer_factor_key) +
                           "=' line; accepted length units: " + std::string(accepted_length_units));
    scale = *metres;
  } else {
    throw InputError(path, header_line,
                     header_name + " has neither a '" + std::string(interferometer_factor_key) +
                         "=' line nor a 'data unit=' line");
  }

  const PromisedShape promised{
      rows, columns, "h=" + std::to_string(rows) + " (line " + std::to_string(h.line) + ")",
      "w=" + std::to_string(columns) + " (line " + std::to_string(w.line) + ")", h.line};
  DataBlock block = parse_data(path, lines.subspan(header_size), scale, promised, " after the " + header_name,
                               header_text_syntax());
  return single_height_channel(std::move(block), std::string(factor.line != 0 ? "m" : data_unit.value), lx,
                               ly);
}

}  // namespace contactbench::formats
