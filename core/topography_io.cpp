#include "contactbench/core/topography_io.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <span>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/bounded_read.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view project_magic = "# contactbench surface v1";
constexpr std::string_view project_prefix = "# contactbench surface";
constexpr std::string_view interferometer_factor_key = "height conversion factor (-> m)";
constexpr std::string_view accepted_length_units = "m, mm, um, \u00b5m, \u03bcm, nm";
// Sizes the caller gives must match the file's to this relative tolerance (TopographyReadOptions).
constexpr Real size_agreement = 1e-6;
// Offending tokens are quoted in messages; a binary file must not produce a megabyte-long message.
constexpr std::size_t max_quoted_length = 40;

// One non-blank line of a file: its text without line end and outer blanks, and its 1-based number.
struct Line {
  std::string_view text;
  long number = 0;
};

// A header value and the line it came from (line 0: absent).
struct HeaderEntry {
  std::string_view value;
  long line = 0;
};

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

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front()))
    text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back()))
    text.remove_suffix(1);
  return text;
}

std::vector<std::string_view> split_blanks(std::string_view text) {
  std::vector<std::string_view> tokens;
  std::size_t position = 0;
  while (position < text.size()) {
    while (position < text.size() && is_blank(text[position]))
      ++position;
    const std::size_t start = position;
    while (position < text.size() && !is_blank(text[position]))
      ++position;
    if (position > start) tokens.push_back(text.substr(start, position - start));
  }
  return tokens;
}

// ASCII case-insensitive equality, for header keys that tools spell with varying capitals.
bool equals_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

// A token as a message shows it: control bytes and bytes that are not UTF-8 as \xNN (a NUL would end the
// message, a raw binary byte garble the terminal), cut after max_quoted_length characters.
std::string quoted(std::string_view token) {
  const bool cut = token.size() > max_quoted_length;
  if (cut) token = token.substr(0, max_quoted_length);
  std::string text = "'";
  for (std::size_t i = 0; i < token.size(); ++i) {
    const auto byte = static_cast<unsigned char>(token[i]);
    // A UTF-8 sequence: its lead byte says how many continuation bytes (10xxxxxx) follow.
    const std::size_t length = byte >= 0xf0 && byte < 0xf8 ? 4 : byte >= 0xe0 ? 3 : byte >= 0xc2 ? 2 : 1;
    bool sequence = byte >= 0xc2 && byte < 0xf8 && i + length <= token.size();
    for (std::size_t k = 1; sequence && k < length; ++k)
      sequence = (static_cast<unsigned char>(token[i + k]) & 0xc0) == 0x80;
    if (sequence) {
      text.append(token.substr(i, length));
      i += length - 1;
    } else if (byte < 0x20 || byte >= 0x7f) {
      char escaped[5];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
      text += escaped;
    } else {
      text += static_cast<char>(byte);
    }
  }
  return text + (cut ? "...'" : "'");
}

// Text formats only: UTF-16 text and binary bytes are named as such before any parsing (their first token
// would otherwise be reported as "not a number", or as a matrix without a size).
void check_is_text(const fs::path& path, std::string_view bytes) {
  if (bytes.starts_with("\xff\xfe") || bytes.starts_with("\xfe\xff"))
    throw InputError(path, 0,
                     "is UTF-16 text (it starts with a UTF-16 byte order mark): save it as UTF-8 or ASCII "
                     "text, or give a format contactbench reads (docs/formats.md)");
  const std::size_t nul = bytes.substr(0, 65536).find('\0');
  if (nul != std::string_view::npos)
    throw InputError(path, 0,
                     "holds binary data (a NUL byte at offset " + std::to_string(nul) +
                         ") in none of the binary formats contactbench reads (docs/formats.md lists them); a "
                         "text topography holds numbers as text");
}

// Shortest decimal that reads back to the same double.
std::string format_real(Real value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string line_range(std::span<const Line> lines) {
  if (lines.empty()) return "no lines";
  if (lines.size() == 1) return "line " + std::to_string(lines.front().number);
  return "lines " + std::to_string(lines.front().number) + "-" + std::to_string(lines.back().number);
}

// std::from_chars, which rejects a leading '+' that instruments and people sometimes write.
std::from_chars_result parse_real_prefix(const char* first, const char* last, Real& value) {
  if (last - first > 1 && *first == '+' &&
      (std::isdigit(static_cast<unsigned char>(first[1])) || first[1] == '.'))
    ++first;
  return std::from_chars(first, last, value);
}

// The whole token as a double (possibly NaN or Inf), or nothing if it is not exactly one number in range.
std::optional<Real> parse_real(std::string_view token) {
  Real value = 0;
  const char* last = token.data() + token.size();
  const auto [end, error] = parse_real_prefix(token.data(), last, value);
  if (error != std::errc() || end != last) return std::nullopt;
  return value;
}

std::optional<Real> length_unit_in_metres(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\u00b5m" || unit == "\u03bcm") return 1e-6;
  if (unit == "nm") return 1e-9;
  return std::nullopt;
}

Real length_unit_or_throw(const fs::path& path, long line, std::string_view what, std::string_view unit) {
  const std::optional<Real> metres = length_unit_in_metres(unit);
  if (!metres)
    throw InputError(path, line,
                     "unknown unit " + quoted(unit) + " for " + std::string(what) +
                         "; accepted length units: " + std::string(accepted_length_units));
  return *metres;
}

// A lateral size written as "<number> <unit>" (or "<number><unit>"), in metres; finite and > 0.
Real parse_size(const fs::path& path, long line, std::string_view key, std::string_view text) {
  Real value = 0;
  const char* last = text.data() + text.size();
  const auto [end, error] = parse_real_prefix(text.data(), last, value);
  if (error != std::errc() || end == text.data())
    throw InputError(path, line, std::string(key) + " needs a number and a length unit, got " + quoted(text));
  const std::string_view unit = trim(std::string_view(end, static_cast<std::size_t>(last - end)));
  if (unit.empty())
    throw InputError(path, line,
                     std::string(key) + " " + quoted(text) +
                         " has no unit; accepted length units: " + std::string(accepted_length_units));
  const Real metres = value * length_unit_or_throw(path, line, key, unit);
  if (!(std::isfinite(metres) && metres > 0))
    throw InputError(path, line, std::string(key) + " must be a finite size > 0, got " + quoted(text));
  return metres;
}

Index parse_count(const fs::path& path, long line, std::string_view key, std::string_view text) {
  long long count = 0;
  const char* last = text.data() + text.size();
  const auto [end, error] = std::from_chars(text.data(), last, count);
  if (error != std::errc() || end != last || count < 1)
    throw InputError(path, line, std::string(key) + " must be a whole number >= 1, got " + quoted(text));
  return static_cast<Index>(count);
}

void check_lateral_size(const fs::path& path, long line, std::string_view name, Real value) {
  if (!(std::isfinite(value) && value > 0))
    throw InputError(path, line,
                     std::string(name) + " = " + format_real(value) + " m is not a finite size > 0");
}

// A size the caller gave must match the one the file carries.
void check_agrees(const fs::path& path, long line, std::string_view name, Real from_file,
                  const std::optional<Real>& given) {
  if (!given) return;
  if (!(std::abs(*given - from_file) <= size_agreement * from_file))
    throw InputError(path, line,
                     "the file gives " + std::string(name) + " = " + format_real(from_file) +
                         " m but the caller gave " + std::string(name) + " = " + format_real(*given) +
                         " m; they must agree to 1e-6 relative");
}

void store_entry(const fs::path& path, const Line& line, std::string_view key, std::string_view value,
                 HeaderEntry& entry) {
  if (entry.line != 0)
    throw InputError(
        path, line.number,
        "header key " + quoted(key) + " given twice (first on line " + std::to_string(entry.line) + ")");
  entry = {value, line.number};
}

std::string read_whole_file(const fs::path& path) {
  return read_file_bounded(path, kMaxTopographyFileBytes, "topographies");
}

// Splits at LF, CRLF or a lone CR, numbering lines from 1, and keeps the non-blank ones.
std::vector<Line> non_blank_lines(std::string_view content) {
  constexpr std::string_view utf8_byte_order_mark = "\xEF\xBB\xBF";
  if (content.starts_with(utf8_byte_order_mark)) content.remove_prefix(utf8_byte_order_mark.size());
  std::vector<Line> lines;
  long number = 0;
  std::size_t start = 0;
  while (start < content.size()) {
    std::size_t end = content.find_first_of("\r\n", start);
    if (end == std::string_view::npos) end = content.size();
    ++number;
    const std::string_view text = trim(content.substr(start, end - start));
    if (!text.empty()) lines.push_back({text, number});
    start = end;
    if (start < content.size()) {
      const bool crlf = content[start] == '\r' && start + 1 < content.size() && content[start + 1] == '\n';
      start += crlf ? 2 : 1;
    }
  }
  return lines;
}

TopographyFormat format_of(const fs::path& path, std::span<const Line> lines) {
  if (lines.empty()) throw InputError(path, 0, "empty file: no data rows");
  const std::string_view first = lines.front().text;
  if (first.starts_with(project_prefix)) return TopographyFormat::project;
  if (first.starts_with("h=")) return TopographyFormat::interferometer;
  if (first.starts_with('#')) return TopographyFormat::gwyddion;
  return TopographyFormat::plain_matrix;
}

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

// Parses every line as a row of heights: same count on every row, and the header's counts if it gave any.
DataBlock parse_data(const fs::path& path, std::span<const Line> lines, Real scale,
                     const std::optional<PromisedShape>& promised, std::string_view context) {
  if (lines.empty()) throw InputError(path, 0, "no data rows" + std::string(context));
  DataBlock block;
  long first_row_line = 0;
  for (const Line& line : lines) {
    if (promised && block.rows == promised->rows)
      throw InputError(path, line.number, "more data rows than the header's " + promised->rows_name);
    const std::size_t before = block.values.size();
    const char* position = line.text.data();
    const char* const end = position + line.text.size();
    while (position < end) {
      while (position < end && is_blank(*position))
        ++position;
      const char* const start = position;
      while (position < end && !is_blank(*position))
        ++position;
      if (position > start)
        block.values.push_back(parse_height(
            path, line.number, std::string_view(start, static_cast<std::size_t>(position - start)), scale));
    }
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

// "h=650 w=650" holds several key=value pairs; "pixel size=3.7e-7 m" is one key (with a blank) and its value.
std::vector<std::pair<std::string_view, std::string_view>> key_value_pairs(std::string_view text) {
  std::vector<std::pair<std::string_view, std::string_view>> pairs;
  const std::vector<std::string_view> tokens = split_blanks(text);
  const bool all_pairs = std::all_of(tokens.begin(), tokens.end(),
                                     [](std::string_view token) { return token.find('=') != token.npos; });
  const auto split = [](std::string_view item) {
    const std::size_t equals = item.find('=');
    return std::pair{trim(item.substr(0, equals)), trim(item.substr(equals + 1))};
  };
  if (all_pairs) {
    for (const std::string_view token : tokens)
      pairs.push_back(split(token));
  } else {
    pairs.push_back(split(text));
  }
  return pairs;
}

Surface read_project(const fs::path& path, std::span<const Line> lines,
                     const TopographyReadOptions& options) {
  const Line& magic = lines.front();
  if (magic.text != project_magic)
    throw InputError(path, magic.number,
                     "unsupported project format header " + quoted(magic.text) + "; this reader knows " +
                         quoted(project_magic));
  if (lines.size() < 2 || !lines[1].text.starts_with('#'))
    throw InputError(
        path, magic.number,
        "the project format needs a second line '# nx=... ny=... lx=... ly=... periodic=... unit=m'");
  const Line& header = lines[1];
  HeaderEntry nx, ny, lx, ly, periodic, unit;
  for (const std::string_view token : split_blanks(header.text.substr(1))) {
    const std::size_t equals = token.find('=');
    if (equals == token.npos)
      throw InputError(path, header.number, "expected key=value in the header, got " + quoted(token));
    const std::string_view key = token.substr(0, equals);
    const std::string_view value = token.substr(equals + 1);
    HeaderEntry* entry = key == "nx"         ? &nx
                         : key == "ny"       ? &ny
                         : key == "lx"       ? &lx
                         : key == "ly"       ? &ly
                         : key == "periodic" ? &periodic
                         : key == "unit"     ? &unit
                                             : nullptr;
    if (entry == nullptr)
      throw InputError(path, header.number,
                       "unknown header key " + quoted(key) + "; expected nx, ny, lx, ly, periodic, unit");
    store_entry(path, header, key, value, *entry);
  }
  for (const auto& [key, entry] :
       {std::pair{"nx", nx}, std::pair{"ny", ny}, std::pair{"lx", lx}, std::pair{"ly", ly},
        std::pair{"periodic", periodic}, std::pair{"unit", unit}})
    if (entry.line == 0) throw InputError(path, header.number, "header has no " + std::string(key) + "=");
  if (unit.value != "m")
    throw InputError(path, header.number,
                     "the project format stores metres (unit=m), got unit=" + quoted(unit.value));
  if (periodic.value != "true" && periodic.value != "false")
    throw InputError(path, header.number, "periodic must be true or false, got " + quoted(periodic.value));

  const Index columns = parse_count(path, header.number, "nx", nx.value);
  const Index rows = parse_count(path, header.number, "ny", ny.value);
  const std::optional<Real> size_x = parse_real(lx.value);
  const std::optional<Real> size_y = parse_real(ly.value);
  if (!size_x) throw InputError(path, header.number, "lx=" + quoted(lx.value) + " is not a number");
  if (!size_y) throw InputError(path, header.number, "ly=" + quoted(ly.value) + " is not a number");
  check_lateral_size(path, header.number, "lx", *size_x);
  check_lateral_size(path, header.number, "ly", *size_y);
  check_agrees(path, header.number, "lx", *size_x, options.lx);
  check_agrees(path, header.number, "ly", *size_y, options.ly);

  const std::string where = " (line " + std::to_string(header.number) + ")";
  const PromisedShape promised{rows, columns, "ny=" + std::to_string(rows) + where,
                               "nx=" + std::to_string(columns) + where, header.number};
  // Scale 1: multiplying by 1.0 is exact, so the heights stay bit for bit what was written.
  DataBlock block = parse_data(path, lines.subspan(2), 1.0, promised, " after the header");
  return make_surface(std::move(block), *size_x, *size_y,
                      options.periodic.value_or(periodic.value == "true"));
}

Surface read_interferometer(const fs::path& path, std::span<const Line> lines,
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
  DataBlock block =
      parse_data(path, lines.subspan(header_size), scale, promised, " after the " + header_name);
  return make_surface(std::move(block), lx, ly, options.periodic.value_or(false));
}

Surface read_gwyddion(const fs::path& path, std::span<const Line> lines,
                      const TopographyReadOptions& options) {
  std::size_t header_size = 0;
  while (header_size < lines.size() && lines[header_size].text.starts_with('#'))
    ++header_size;
  const std::span<const Line> header = lines.first(header_size);

  HeaderEntry width, height, value_units;
  for (const Line& line : header) {
    const std::string_view body = line.text.substr(1);
    const std::size_t colon = body.find(':');
    if (colon == std::string_view::npos) continue;  // a comment, not a key
    const std::string_view key = trim(body.substr(0, colon));
    const std::string_view value = trim(body.substr(colon + 1));
    HeaderEntry* entry = equals_ignoring_case(key, "Width")         ? &width
                         : equals_ignoring_case(key, "Height")      ? &height
                         : equals_ignoring_case(key, "Value units") ? &value_units
                                                                    : nullptr;
    if (entry != nullptr) store_entry(path, line, key, value, *entry);  // Channel and others: not needed
  }
  const long header_line = header.front().number;
  const std::string header_name = "Gwyddion header (" + line_range(header) + ")";
  for (const auto& [key, entry] :
       {std::pair{"Width", width}, std::pair{"Height", height}, std::pair{"Value units", value_units}})
    if (entry.line == 0)
      throw InputError(path, header_line, header_name + " has no '# " + key + ": ...' line");

  const Real lx = parse_size(path, width.line, "Width", width.value);
  const Real ly = parse_size(path, height.line, "Height", height.value);
  check_agrees(path, width.line, "lx", lx, options.lx);
  check_agrees(path, height.line, "ly", ly, options.ly);
  const Real scale = length_unit_or_throw(path, value_units.line, "Value units", value_units.value);

  DataBlock block =
      parse_data(path, lines.subspan(header_size), scale, std::nullopt, " after the " + header_name);
  return make_surface(std::move(block), lx, ly, options.periodic.value_or(false));
}

Surface read_plain_matrix(const fs::path& path, std::span<const Line> lines,
                          const TopographyReadOptions& options) {
  if (!options.lx)
    throw InputError(path, 0, "no lateral size: a plain matrix needs the caller's size (--size)");
  check_lateral_size(path, 0, "the given lx", *options.lx);
  if (options.ly) check_lateral_size(path, 0, "the given ly", *options.ly);
  DataBlock block = parse_data(path, lines, 1.0, std::nullopt, "");
  // Square pixels unless told otherwise: ly / ny = lx / nx.
  const Real ly =
      options.ly.value_or(*options.lx * static_cast<Real>(block.rows) / static_cast<Real>(block.cols));
  check_lateral_size(path, 0, "ly (square pixels from the given lx)", ly);
  return make_surface(std::move(block), *options.lx, ly, options.periodic.value_or(false));
}

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

std::string_view to_string(TopographyFormat format) {
  switch (format) {
    case TopographyFormat::x3p:
      return "x3p";
    case TopographyFormat::sdf:
      return "sdf";
    case TopographyFormat::npy:
      return "npy";
    case TopographyFormat::metropro:
      return "metropro";
    case TopographyFormat::nanoscope:
      return "nanoscope";
    case TopographyFormat::sensofar:
      return "sensofar";
    case TopographyFormat::digital_surf:
      return "digital_surf";
    case TopographyFormat::wyko:
      return "wyko";
    case TopographyFormat::netcdf:
      return "netcdf";
    case TopographyFormat::project:
      return "project";
    case TopographyFormat::interferometer:
      return "interferometer";
    case TopographyFormat::gwyddion:
      return "gwyddion";
    case TopographyFormat::plain_matrix:
      return "plain_matrix";
  }
  throw Error("unknown topography format " + std::to_string(static_cast<int>(format)));
}

bool format_carries_sizes(TopographyFormat format) {
  return format != TopographyFormat::npy && format != TopographyFormat::plain_matrix;
}

namespace {

// The binary formats: how each is recognised and read (docs/formats.md).
struct BinaryFormat {
  TopographyFormat format;
  std::array<std::string_view, 3> extensions;  // lower case, with the dot; "" for unused slots
  bool (*detect)(std::string_view bytes);
  formats::RawTopography (*read)(const fs::path& path, std::string_view bytes);
};

constexpr std::array<BinaryFormat, 9> binary_formats = {{
    {TopographyFormat::x3p, {".x3p", "", ""}, formats::looks_like_zip, formats::read_x3p},
    {TopographyFormat::sdf, {".sdf", "", ""}, formats::looks_like_sdf, formats::read_sdf},
    {TopographyFormat::npy, {".npy", "", ""}, formats::looks_like_npy, formats::read_npy},
    {TopographyFormat::metropro, {".dat", "", ""}, formats::looks_like_metropro, formats::read_metropro},
    {TopographyFormat::nanoscope,
     {".di", ".spm", ""},
     formats::looks_like_nanoscope,
     formats::read_nanoscope},
    {TopographyFormat::digital_surf,
     {".sur", "", ""},
     formats::looks_like_digital_surf,
     formats::read_digital_surf},
    {TopographyFormat::wyko, {".opd", "", ""}, formats::looks_like_wyko, formats::read_wyko},
    {TopographyFormat::netcdf, {".nc", "", ""}, formats::looks_like_netcdf, formats::read_netcdf},
    // Last: .plu has no magic, only a self-consistent header.
    {TopographyFormat::sensofar, {".plu", "", ""}, formats::looks_like_sensofar, formats::read_sensofar},
}};

std::string lower_extension(const fs::path& path) {
  std::string extension = path.extension().string();
  for (char& c : extension)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return extension;
}

// The binary format of these bytes: by content first; else by an extension that names one (its reader then
// refuses the file with what is wrong); else none (a text format).
const BinaryFormat* binary_format_of(const fs::path& path, std::string_view bytes) {
  for (const BinaryFormat& candidate : binary_formats)
    if (candidate.detect(bytes)) return &candidate;
  const std::string extension = lower_extension(path);
  for (const BinaryFormat& candidate : binary_formats)
    for (const std::string_view known : candidate.extensions)
      if (!known.empty() && extension == known) return &candidate;
  return nullptr;
}

std::string channel_list(const formats::RawTopography& raw) {
  std::string list;
  for (std::size_t k = 0; k < raw.channels.size(); ++k) {
    const formats::Channel& channel = raw.channels[k];
    if (k > 0) list += ", ";
    list += std::to_string(k) + " '" + channel.name + "'" + (channel.is_height ? "" : " (not a height)");
  }
  return list;
}

std::size_t select_channel(const fs::path& path, const formats::RawTopography& raw,
                           const std::optional<std::string>& wanted) {
  if (!wanted) {
    for (std::size_t k = 0; k < raw.channels.size(); ++k)
      if (raw.channels[k].is_height) return k;
    throw InputError(path, 0, "no height channel; the file's channels: " + channel_list(raw));
  }
  std::optional<std::size_t> chosen;
  const bool digits = !wanted->empty() && std::all_of(wanted->begin(), wanted->end(),
                                                      [](char c) { return c >= '0' && c <= '9'; });
  if (digits && wanted->size() < 9) {
    const std::size_t index = std::stoul(*wanted);
    if (index < raw.channels.size()) chosen = index;
  } else {
    for (std::size_t k = 0; k < raw.channels.size() && !chosen; ++k)
      if (raw.channels[k].name == *wanted) chosen = k;
  }
  if (!chosen)
    throw InputError(path, 0, "unknown channel '" + *wanted + "'; the file's channels: " + channel_list(raw));
  if (!raw.channels[*chosen].is_height)
    throw InputError(
        path, 0,
        "channel '" + *wanted + "' does not hold heights; the file's channels: " + channel_list(raw));
  return *chosen;
}

TopographyReading read_binary(const fs::path& path, std::string_view bytes, const BinaryFormat& format,
                              const TopographyReadOptions& options) {
  formats::RawTopography raw = format.read(path, bytes);
  const std::size_t index = select_channel(path, raw, options.channel);
  formats::Channel& channel = raw.channels[index];

  Real lx = 0;
  Real ly = 0;
  if (channel.lx && channel.ly) {
    check_lateral_size(path, 0, "lx", *channel.lx);
    check_lateral_size(path, 0, "ly", *channel.ly);
    check_agrees(path, 0, "lx", *channel.lx, options.lx);
    check_agrees(path, 0, "ly", *channel.ly, options.ly);
    lx = *channel.lx;
    ly = *channel.ly;
  } else {
    if (!options.lx)
      throw InputError(path, 0,
                       "no lateral size: a " + std::string(to_string(format.format)) +
                           " file carries none, so the caller must give it (--size)");
    check_lateral_size(path, 0, "the given lx", *options.lx);
    lx = *options.lx;
    ly = options.ly.value_or(lx * static_cast<Real>(channel.ny) / static_cast<Real>(channel.nx));
    check_lateral_size(path, 0, "ly", ly);
  }

  const auto invalid = static_cast<Index>(
      std::count_if(channel.values.begin(), channel.values.end(), [](Real v) { return std::isnan(v); }));
  if (invalid > 0 && options.fill == FillMethod::none)
    throw InputError(path, 0,
                     std::to_string(invalid) + " of " + std::to_string(channel.values.size()) +
                         " points of channel '" + channel.name +
                         "' are invalid (not measured); they are never used as heights: choose fill = "
                         "\"harmonic\" or \"mean\" (--fill) to fill them");
  try {
    fill_invalid_points(channel.values, channel.nx, channel.ny, options.fill);
  } catch (const InputError&) {
    throw;
  } catch (const Error& error) {
    throw InputError(path, 0, "channel '" + channel.name + "': " + error.what());
  }
  for (const Real value : channel.values)
    if (!std::isfinite(value))
      throw InputError(path, 0,
                       "channel '" + channel.name + "' holds a height that is not finite after scaling");

  const Grid grid{channel.nx, channel.ny, lx, ly, options.periodic.value_or(raw.periodic)};
  HeightMap heights = Eigen::Map<const HeightMap>(channel.values.data(), channel.ny, channel.nx);
  level_heights(heights, grid, options.level);
  std::vector<std::string> names;
  for (const formats::Channel& c : raw.channels)
    names.push_back(c.name);
  return TopographyReading{Surface(grid, std::move(heights)),
                           format.format,
                           channel.name,
                           std::move(names),
                           invalid,
                           options.fill,
                           options.level};
}

}  // namespace

TopographyFormat detect_topography_format(const std::filesystem::path& path) {
  const std::string content = read_whole_file(path);
  if (const BinaryFormat* binary = binary_format_of(path, content)) return binary->format;
  return format_of(path, non_blank_lines(content));
}

formats::RawTopography read_topography_channels(const std::filesystem::path& path) {
  const std::string content = read_whole_file(path);
  const BinaryFormat* binary = binary_format_of(path, content);
  if (binary == nullptr)
    throw InputError(path, 0, "a text topography has one channel; read it with read_topography");
  return binary->read(path, content);
}

TopographyReading read_topography_reading(const std::filesystem::path& path,
                                          const TopographyReadOptions& options) {
  const std::string content = read_whole_file(path);
  if (const BinaryFormat* binary = binary_format_of(path, content))
    return read_binary(path, content, *binary, options);

  check_is_text(path, content);
  const std::vector<Line> lines = non_blank_lines(content);
  const TopographyFormat format = format_of(path, lines);
  // Text formats hold one channel, called "height" (index 0).
  if (options.channel && *options.channel != "height" && *options.channel != "0")
    throw InputError(path, 0, "unknown channel '" + *options.channel + "'; the file's channels: 0 'height'");
  Surface surface = [&] {
    switch (format) {
      case TopographyFormat::project:
        return read_project(path, lines, options);
      case TopographyFormat::interferometer:
        return read_interferometer(path, lines, options);
      case TopographyFormat::gwyddion:
        return read_gwyddion(path, lines, options);
      default:
        return read_plain_matrix(path, lines, options);
    }
  }();
  if (options.level != Levelling::none) {
    HeightMap heights = surface.heights();
    level_heights(heights, surface.grid(), options.level);
    surface = Surface(surface.grid(), std::move(heights));
  }
  return TopographyReading{std::move(surface), format, "height", {"height"}, 0, options.fill, options.level};
}

Surface read_topography(const std::filesystem::path& path, const TopographyReadOptions& options) {
  return read_topography_reading(path, options).surface;
}

void write_topography(const std::filesystem::path& path, const Surface& surface) {
  const std::string extension = lower_extension(path);
  if (extension == ".x3p") return formats::write_x3p(path, surface);
  if (extension == ".npy") return formats::write_npy(path, surface);
  write_surface(path, surface);
}

void write_surface(const std::filesystem::path& path, const Surface& surface) {
  const Grid& grid = surface.grid();
  const std::string header = std::string(project_magic) + "\n# nx=" + std::to_string(grid.nx) +
                             " ny=" + std::to_string(grid.ny) + " lx=" + format_real(grid.lx) +
                             " ly=" + format_real(grid.ly) +
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
