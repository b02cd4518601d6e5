// NetCDF (.nc) as ContactMechanics and Tamaas write a topography, docs/formats.md "netcdf": the classic
// format (CDF-1, the 64-bit-offset CDF-2 and the 64-bit-data CDF-5), parsed here with bounds checks (the
// NetCDF library allocates whatever a corrupt header asks for, so it is not used). A variable "heights" with
// two dimensions (x, y), x the slow index; optional variables "x" and "y" whose attributes give the sizes
// ("length"), the unit ("unit") and periodicity ("periodic"). NetCDF-4 (HDF5) files are refused with a hint.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// Tags and types of the classic format specification.
constexpr std::uint32_t tag_dimension = 0x0A;
constexpr std::uint32_t tag_variable = 0x0B;
constexpr std::uint32_t tag_attribute = 0x0C;

std::optional<std::size_t> type_size(std::uint32_t type) {
  switch (type) {
    case 1:  // byte
    case 2:  // char
    case 7:  // ubyte
      return 1;
    case 3:  // short
    case 8:  // ushort
      return 2;
    case 4:  // int
    case 5:  // float
    case 9:  // uint
      return 4;
    case 6:   // double
    case 10:  // int64
    case 11:  // uint64
      return 8;
    default:
      return std::nullopt;
  }
}

double decode_number(const char* source, std::uint32_t type) {
  constexpr ByteOrder big = ByteOrder::big;
  switch (type) {
    case 1:
      return static_cast<std::int8_t>(*source);
    case 7:
      return static_cast<std::uint8_t>(*source);
    case 3:
      return BinaryView::decode<std::int16_t>(source, big);
    case 8:
      return BinaryView::decode<std::uint16_t>(source, big);
    case 4:
      return BinaryView::decode<std::int32_t>(source, big);
    case 9:
      return BinaryView::decode<std::uint32_t>(source, big);
    case 5:
      return BinaryView::decode<float>(source, big);
    case 10:
      return static_cast<double>(BinaryView::decode<std::int64_t>(source, big));
    case 11:
      return static_cast<double>(BinaryView::decode<std::uint64_t>(source, big));
    default:
      return BinaryView::decode<double>(source, big);
  }
}

struct Attribute {
  std::string text;             // for char attributes
  std::optional<double> first;  // the first value of a numeric attribute
};
using Attributes = std::map<std::string, Attribute>;

struct Variable {
  std::vector<std::uint64_t> dimensions;  // dimension ids
  Attributes attributes;
  std::uint32_t type = 0;
  std::uint64_t begin = 0;
};

// Reads the header front to back; every count is checked against the bytes left before anything is sized.
class Header {
 public:
  Header(const BinaryView& view, int version) : view_(view), wide_(version == 5), offset64_(version != 1) {}

  // Counts are 8 bytes in CDF-5, else 4; offsets 8 bytes from CDF-2 on.
  std::uint64_t count(std::string_view what) { return unsigned_field(wide_, what); }
  std::uint64_t offset(std::string_view what) { return unsigned_field(offset64_, what); }
  std::uint32_t tag(std::string_view what) {
    const auto value = view_.read<std::uint32_t>(at_, ByteOrder::big, what);
    at_ += 4;
    return value;
  }
  // A list's element count, refused when even the smallest elements (4 bytes each) could not fit.
  std::uint64_t list_length(std::string_view what) {
    const std::uint64_t n = count(what);
    if (n > (view_.size() - std::min<std::uint64_t>(at_, view_.size())) / 4)
      throw InputError(view_.path(), 0,
                       "truncated or corrupt: the NetCDF header lists " + std::to_string(n) + " " +
                           std::string(what) + ", more than the file can hold");
    return n;
  }
  std::string_view padded(std::uint64_t length, std::string_view what) {
    const std::string_view bytes = view_.slice(at_, length, what);
    at_ += (length + 3) / 4 * 4;
    return bytes;
  }
  std::string name(std::string_view what) {
    const std::uint64_t length = count(what);
    return std::string(padded(length, what));
  }
  Attributes attributes() {
    Attributes result;
    const std::uint32_t list_tag = tag("attribute list tag");
    const std::uint64_t n = list_length("attributes");
    if (list_tag != tag_attribute && !(list_tag == 0 && n == 0))
      throw InputError(view_.path(), 0, "corrupt NetCDF header: bad attribute list tag");
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::string key = name("attribute name");
      const std::uint32_t type = tag("attribute type");
      const std::optional<std::size_t> size = type_size(type);
      if (!size)
        throw InputError(view_.path(), 0,
                         "unknown NetCDF data type " + std::to_string(type) + " of attribute '" + key + "'");
      const std::uint64_t values = count("attribute length");
      if (values > view_.size() / *size)
        throw InputError(view_.path(), 0,
                         "truncated or corrupt: NetCDF attribute '" + key + "' is longer than the file");
      const std::string_view bytes = padded(values * *size, "attribute '" + key + "'");
      Attribute attribute;
      if (type == 2) {
        attribute.text = std::string(bytes);
        while (!attribute.text.empty() && attribute.text.back() == '\0')
          attribute.text.pop_back();
      } else if (values > 0) {
        attribute.first = decode_number(bytes.data(), type);
      }
      result[key] = std::move(attribute);
    }
    return result;
  }

 private:
  // A big-endian unsigned of 8 bytes (`eight`) or 4 at the cursor; the cursor moves past it.
  std::uint64_t unsigned_field(bool eight, std::string_view what) {
    const std::uint64_t value = eight ? view_.read<std::uint64_t>(at_, ByteOrder::big, what)
                                      : view_.read<std::uint32_t>(at_, ByteOrder::big, what);
    at_ += eight ? 8 : 4;
    return value;
  }

  const BinaryView& view_;
  bool wide_;
  bool offset64_;
  std::uint64_t at_ = 4;
};

std::optional<Real> netcdf_length_unit(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "um" || unit == "\xc2\xb5m" || unit == "\xce\xbcm") return 1e-6;
  if (unit == "nm") return 1e-9;
  if (unit == "pm") return 1e-12;
  return std::nullopt;
}

}  // namespace

bool looks_like_netcdf(std::string_view bytes) {
  return bytes.starts_with("CDF\x01") || bytes.starts_with("CDF\x02") || bytes.starts_with("CDF\x05") ||
         bytes.starts_with("\x89HDF\r\n\x1a\n");
}

RawTopography read_netcdf(const fs::path& path, std::string_view bytes) {
  if (!looks_like_netcdf(bytes))
    throw InputError(path, 0, "wrong magic: a NetCDF file begins with 'CDF' and a version byte 1, 2 or 5");
  if (bytes.front() != 'C')
    throw InputError(path, 0,
                     "a NetCDF-4 (HDF5) file; only the classic formats are read (convert with "
                     "'nccopy -k nc7 IN OUT')");
  const BinaryView view(path, bytes);
  Header header(view, bytes[3]);

  (void)header.count("number of records");
  std::vector<std::pair<std::string, std::uint64_t>> dimensions;
  {
    const std::uint32_t list_tag = header.tag("dimension list tag");
    const std::uint64_t n = header.list_length("dimensions");
    if (list_tag != tag_dimension && !(list_tag == 0 && n == 0))
      throw InputError(path, 0, "corrupt NetCDF header: bad dimension list tag");
    for (std::uint64_t k = 0; k < n; ++k) {
      std::string name = header.name("dimension name");
      dimensions.emplace_back(std::move(name), header.count("dimension length"));
    }
  }
  (void)header.attributes();  // global attributes: nothing needed
  std::map<std::string, Variable> variables;
  {
    const std::uint32_t list_tag = header.tag("variable list tag");
    const std::uint64_t n = header.list_length("variables");
    if (list_tag != tag_variable && !(list_tag == 0 && n == 0))
      throw InputError(path, 0, "corrupt NetCDF header: bad variable list tag");
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::string name = header.name("variable name");
      Variable variable;
      const std::uint64_t rank = header.list_length("variable dimensions");
      for (std::uint64_t d = 0; d < rank; ++d)
        variable.dimensions.push_back(header.count("dimension id"));
      variable.attributes = header.attributes();
      variable.type = header.tag("variable type");
      (void)header.count("variable size");
      variable.begin = header.offset("variable offset");
      variables[name] = std::move(variable);
    }
  }

  const auto heights = variables.find("heights");
  if (heights == variables.end()) throw InputError(path, 0, "the NetCDF file has no variable 'heights'");
  const Variable& h = heights->second;
  if (h.dimensions.size() != 2)
    throw InputError(
        path, 0,
        "NetCDF 'heights' has " + std::to_string(h.dimensions.size()) + " dimensions; a topography needs 2");
  for (const std::uint64_t id : h.dimensions)
    if (id >= dimensions.size())
      throw InputError(path, 0, "corrupt NetCDF header: 'heights' names a missing dimension");
  const std::uint64_t nx = dimensions[h.dimensions[0]].second;
  const std::uint64_t ny = dimensions[h.dimensions[1]].second;
  if (nx == 0 || ny == 0)
    throw InputError(path, 0, "NetCDF 'heights' along a record (unlimited) dimension is not read");
  const std::optional<std::size_t> item = type_size(h.type);
  if (!item || h.type == 2)
    throw InputError(path, 0, "NetCDF 'heights' has unknown or non-numeric type " + std::to_string(h.type));
  const std::uint64_t size =
      grid_bytes(path, static_cast<long long>(std::min<std::uint64_t>(nx, 1ull << 40)),
                 static_cast<long long>(std::min<std::uint64_t>(ny, 1ull << 40)), *item, "NetCDF 'heights'");
  const std::string_view data = view.slice(h.begin, size, "NetCDF 'heights' data");

  // Unit and sizes from the coordinate variables' attributes (the heights' unit must agree).
  const auto text_of = [](const Attributes& attributes, const char* key) -> std::optional<std::string> {
    const auto found = attributes.find(key);
    if (found == attributes.end() || found->second.first) return std::nullopt;
    return found->second.text;
  };
  const auto number_of = [](const Attributes& attributes, const char* key) -> std::optional<double> {
    const auto found = attributes.find(key);
    if (found == attributes.end()) return std::nullopt;
    return found->second.first;
  };
  const auto x = variables.find("x");
  const auto y = variables.find("y");
  std::optional<std::string> unit_name =
      x != variables.end() ? text_of(x->second.attributes, "unit") : std::nullopt;
  const std::optional<std::string> height_unit = text_of(h.attributes, "unit");
  if (!unit_name) unit_name = height_unit;
  Real unit = 1;
  if (unit_name) {
    const std::optional<Real> factor = netcdf_length_unit(*unit_name);
    if (!factor)
      throw InputError(path, 0, "NetCDF unit '" + *unit_name + "' is not a length unit (m, mm, um, nm, pm)");
    unit = *factor;
  }
  if (height_unit && *height_unit != *unit_name)
    throw InputError(path, 0, "NetCDF heights are in '" + *height_unit + "' but x in '" + *unit_name + "'");
  std::optional<Real> lx, ly;
  bool periodic = false;
  if (x != variables.end() && y != variables.end()) {
    const std::optional<double> length_x = number_of(x->second.attributes, "length");
    const std::optional<double> length_y = number_of(y->second.attributes, "length");
    if (length_x && length_y) {
      lx = *length_x * unit;
      ly = *length_y * unit;
    }
    if (const std::optional<double> flag = number_of(x->second.attributes, "periodic")) periodic = *flag != 0;
  }
  // Points never written hold the fill value: the variable's _FillValue, else the format's default for
  // doubles.
  const double fill_value = number_of(h.attributes, "_FillValue").value_or(9.9692099683868690e+36);

  Channel channel =
      make_channel("heights", true, unit_name.value_or("m"), static_cast<Index>(nx), static_cast<Index>(ny));
  channel.lx = lx;
  channel.ly = ly;
  allocate_values(path, channel);
  // The file is x-major and the channel y-major: the transpose goes tile by tile, so that both the file's
  // and the channel's lines of a tile stay in cache (column by column it was the slowest read of
  // results/bench/formats_read.md).
  constexpr std::uint64_t tile = 64;
  for (std::uint64_t x0 = 0; x0 < nx; x0 += tile)
    for (std::uint64_t y0 = 0; y0 < ny; y0 += tile)
      for (std::uint64_t ix = x0; ix < std::min(nx, x0 + tile); ++ix)
        for (std::uint64_t iy = y0; iy < std::min(ny, y0 + tile); ++iy) {
          const double value = decode_number(data.data() + (ix * ny + iy) * *item, h.type);
          channel.values[static_cast<std::size_t>(iy * nx + ix)] =
              std::isfinite(value) && value != fill_value ? value * unit
                                                          : std::numeric_limits<Real>::quiet_NaN();
        }
  RawTopography topography;
  topography.periodic = periodic;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats
