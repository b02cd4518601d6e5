// The project's own text format (docs/formats.md "The text formats"): "# contactbench surface v1", a header
// line "# nx=... ny=... lx=... ly=... periodic=... unit=m", then ny rows of nx heights in metres as
// write_surface prints them (shortest round-trip decimals), so reading returns them bit for bit.
#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/height_rows.hpp"
#include "contactbench/core/formats/lateral_sizes.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace fs = std::filesystem;

namespace {

// The project format's values with the quantity and unit its header names: heights (no quantity, unit=m)
// or a field (quantity=pressure unit=Pa, quantity=gap unit=m, ...), written by write_surface / write_field.
struct ProjectValues {
  DataBlock values;
  Real lx = 0, ly = 0;
  bool periodic = false;
  std::string quantity;  // empty: heights
  std::string unit;
};

// `syntax`: heights mark invalid points with NaN or Inf as the other text formats do; a field is refused
// any (its writer writes finite values only).
ProjectValues read_project_values(const fs::path& path, std::span<const Line> lines,
                                  const TopographyReadOptions& options, const RowSyntax& syntax) {
  const ProjectHeader header =
      read_project_header(path, lines.first(std::min<std::size_t>(lines.size(), 2)), options);
  // Scale 1: multiplying by 1.0 is exact, so the heights stay bit for bit what was written.
  DataBlock block =
      parse_data(path, lines.subspan(2), 1.0, header.shape, " after the header", syntax, options.threads);
  return {std::move(block), header.lx, header.ly, header.periodic, header.quantity, header.unit};
}

}  // namespace

ProjectHeader read_project_header(const fs::path& path, std::span<const Line> lines,
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
  HeaderEntry nx, ny, lx, ly, periodic, unit, quantity;
  for (const std::string_view token : split_tokens(header.text.substr(1), is_blank)) {
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
                         : key == "quantity" ? &quantity
                                             : nullptr;
    if (entry == nullptr)
      throw InputError(path, header.number,
                       "unknown header key " + quoted(key) +
                           "; expected nx, ny, lx, ly, periodic, unit (and quantity, in a field file)");
    store_entry(path, header, key, value, *entry);
  }
  for (const auto& [key, entry] :
       {std::pair{"nx", nx}, std::pair{"ny", ny}, std::pair{"lx", lx}, std::pair{"ly", ly},
        std::pair{"periodic", periodic}, std::pair{"unit", unit}})
    if (entry.line == 0) throw InputError(path, header.number, "header has no " + std::string(key) + "=");
  if (quantity.line == 0 && unit.value != "m")
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
  return {PromisedShape{rows, columns, "ny=" + std::to_string(rows) + where,
                        "nx=" + std::to_string(columns) + where, header.number},
          *size_x,
          *size_y,
          periodic.value == "true",
          std::string(quantity.value),
          std::string(unit.value)};
}

// A field in metres (the gap) reads as heights; any other is not a surface.
void require_height_unit(const fs::path& path, const std::string& quantity, const std::string& unit) {
  if (unit != "m")
    throw InputError(
        path, 2,
        "is a " + quantity + " field [" + unit +
            "] written by contactbench, not heights in metres; draw it with `contactbench plot " +
            path.string() + "`");
}

RawTopography read_project(const fs::path& path, std::span<const Line> lines,
                           const TopographyReadOptions& options) {
  ProjectValues read = read_project_values(path, lines, options, header_text_syntax());
  require_height_unit(path, read.quantity, read.unit);
  RawTopography raw = single_height_channel(std::move(read.values), "m", read.lx, read.ly);
  raw.periodic = read.periodic;
  return raw;
}

Field read_project_field(const fs::path& path, std::span<const Line> lines) {
  ProjectValues read = read_project_values(path, lines, {}, RowSyntax{});
  return {make_surface(std::move(read.values), read.lx, read.ly, read.periodic),
          read.quantity.empty() ? "height" : read.quantity, read.unit};
}

}  // namespace contactbench::formats
