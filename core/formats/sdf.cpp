// ISO 25178-71 surface data file (.sdf), docs/formats.md "sdf". ASCII: the magic "aISO-1.0" (older files:
// "aBCR-1.0"), "Key = value" header lines, a '*' line, the values (NumPoints per profile, NumProfiles
// profiles, x fastest; "BAD" marks a missing point), a '*' line. Binary: the magic "bISO-1.0", an 81-byte
// packed little-endian header, then the values. Height = value * Zscale [m]; the point spacings Xscale and
// Yscale are in metres and the lateral size is the count times the spacing.
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

// The data types the standard numbers: 5 int16, 6 int32, 7 float64 (and 3 uint16, 4 uint32, 8 float32).
std::optional<std::size_t> sdf_item_size(int type) {
  switch (type) {
    case 3:
    case 5:
      return 2;
    case 4:
    case 6:
    case 8:
      return 4;
    case 7:
      return 8;
    default:
      return std::nullopt;
  }
}

std::string_view strip(std::string_view text) {
  return trim(text, is_space);
}

Real positive_scale(const fs::path& path, Real value, const char* name) {
  if (!(std::isfinite(value) && value > 0))
    throw InputError(path, 0, std::string("SDF ") + name + " must be a finite number > 0");
  return value;
}

RawTopography make_topography(Index nx, Index ny, Real dx, Real dy, std::vector<Real> values) {
  Channel channel = make_channel("height", true, "m", nx, ny);
  channel.lx = dx * static_cast<Real>(nx);
  channel.ly = dy * static_cast<Real>(ny);
  channel.values = std::move(values);
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

RawTopography read_ascii(const fs::path& path, std::string_view bytes) {
  const std::size_t header_end = bytes.find('*');
  if (header_end == std::string_view::npos)
    throw InputError(path, 0, "truncated SDF: no '*' line closes the header");
  std::map<std::string, std::pair<std::string, long>> header;
  long line_number = 0;
  std::size_t start = 0;
  while (start < header_end) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string_view::npos || end > header_end) end = header_end;
    ++line_number;
    const std::string_view line = strip(bytes.substr(start, end - start));
    const std::size_t equals = line.find('=');
    if (equals != std::string_view::npos)
      header[std::string(strip(line.substr(0, equals)))] = {std::string(strip(line.substr(equals + 1))),
                                                            line_number};
    start = end + 1;
  }
  const auto number = [&](const char* key) {
    const auto found = header.find(key);
    if (found == header.end())
      throw InputError(path, 0, std::string("the SDF header has no '") + key + " = ' line");
    const std::string& text = found->second.first;
    Real value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
      throw InputError(path, found->second.second, std::string(key) + " = '" + text + "' is not a number");
    return value;
  };
  const Real points = number("NumPoints");
  const Real profiles = number("NumProfiles");
  if (points != std::floor(points) || profiles != std::floor(profiles) || !(points >= 1 && profiles >= 1))
    throw InputError(path, 0, "SDF NumPoints and NumProfiles must be whole numbers >= 1");
  const auto nx = static_cast<long long>(std::min(points, 1e18));
  const auto ny = static_cast<long long>(std::min(profiles, 1e18));
  grid_bytes(path, nx, ny, 1, "SDF header");
  const Real dx = positive_scale(path, number("Xscale"), "Xscale");
  const Real dy = positive_scale(path, number("Yscale"), "Yscale");
  const Real dz = number("Zscale");
  if (!(std::isfinite(dz) && dz != 0))
    throw InputError(path, 0, "SDF Zscale must be a finite non-zero number");
  // Checked as a number before it becomes an int: a DataType of 5e10 (found by fuzzing) does not fit one.
  const Real data_type = number("DataType");
  const int type = data_type >= 0 && data_type <= 255 && data_type == std::floor(data_type)
                       ? static_cast<int>(data_type)
                       : -1;
  if (!sdf_item_size(type)) {
    std::ostringstream shown;
    shown << data_type;
    throw InputError(path, 0,
                     "unknown SDF DataType " + shown.str() + "; known: 3, 4, 5, 6 (integers), 7, 8 (floats)");
  }

  // Values from after the header's '*' up to the next '*' (or the end).
  std::size_t data_start = bytes.find('\n', header_end);
  data_start = data_start == std::string_view::npos ? bytes.size() : data_start + 1;
  std::size_t data_end = bytes.find('*', data_start);
  if (data_end == std::string_view::npos) data_end = bytes.size();
  const std::string_view data = bytes.substr(data_start, data_end - data_start);
  const auto expected = static_cast<std::uint64_t>(nx) * static_cast<std::uint64_t>(ny);
  std::vector<Real> values;
  values.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(expected, data.size() / 2 + 1)));
  for_each_token(data, is_space, [&](std::string_view token) {
    if (values.size() == expected)
      throw InputError(path, 0,
                       "the SDF data hold more than the header's " + std::to_string(nx) + " x " +
                           std::to_string(ny) + " values");
    if (token == "BAD") {
      values.push_back(std::numeric_limits<Real>::quiet_NaN());
    } else {
      Real value = 0;
      const auto [stop, error] = std::from_chars(token.data(), token.data() + token.size(), value);
      if (error != std::errc() || stop != token.data() + token.size())
        throw InputError(path, 0, "SDF value '" + std::string(token.substr(0, 40)) + "' is not a number");
      values.push_back(std::isfinite(value) ? value * dz : std::numeric_limits<Real>::quiet_NaN());
    }
  });
  if (values.size() != expected)
    throw InputError(path, 0,
                     "the SDF header promises " + std::to_string(nx) + " x " + std::to_string(ny) + " = " +
                         std::to_string(expected) + " values but the data hold " +
                         std::to_string(values.size()));
  return make_topography(nx, ny, dx, dy, std::move(values));
}

RawTopography read_binary(const fs::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  // Packed header: magic 8, ManufacID 10, CreateDate 12, ModDate 12, NumPoints u16, NumProfiles u16,
  // Xscale, Yscale, Zscale, Zresolution float64, Compression, DataType, CheckType int8: 81 bytes.
  constexpr std::uint64_t header_size = 81;
  view.require(0, header_size, "SDF binary header");
  const auto nx = view.read<std::uint16_t>(42, ByteOrder::little, "NumPoints");
  const auto ny = view.read<std::uint16_t>(44, ByteOrder::little, "NumProfiles");
  const Real dx = positive_scale(path, view.read<double>(46, ByteOrder::little, "Xscale"), "Xscale");
  const Real dy = positive_scale(path, view.read<double>(54, ByteOrder::little, "Yscale"), "Yscale");
  const Real dz = view.read<double>(62, ByteOrder::little, "Zscale");
  if (!(std::isfinite(dz) && dz != 0))
    throw InputError(path, 0, "SDF Zscale must be a finite non-zero number");
  const auto compression = view.read<std::int8_t>(78, ByteOrder::little, "Compression");
  const auto type = view.read<std::int8_t>(79, ByteOrder::little, "DataType");
  if (compression != 0)
    throw InputError(path, 0,
                     "compressed SDF data (Compression " + std::to_string(compression) + ") are not read");
  const std::optional<std::size_t> item = sdf_item_size(type);
  if (!item)
    throw InputError(
        path, 0,
        "unknown SDF DataType " + std::to_string(type) + "; known: 3, 4, 5, 6 (integers), 7, 8 (floats)");
  const std::uint64_t size = grid_bytes(path, nx, ny, *item, "SDF header");
  const std::string_view data = view.slice(header_size, size, "SDF binary data");
  std::vector<Real> values(static_cast<std::size_t>(nx) * ny);
  for (std::size_t k = 0; k < values.size(); ++k) {
    const char* source = data.data() + k * *item;
    Real value = 0;
    bool missing = false;
    switch (type) {
      case 3:
        value = BinaryView::decode<std::uint16_t>(source, ByteOrder::little);
        break;
      case 4:
        value = BinaryView::decode<std::uint32_t>(source, ByteOrder::little);
        break;
      case 5: {
        const auto raw = BinaryView::decode<std::int16_t>(source, ByteOrder::little);
        missing = raw == std::numeric_limits<std::int16_t>::min();  // the standard's missing-point value
        value = raw;
        break;
      }
      case 6: {
        const auto raw = BinaryView::decode<std::int32_t>(source, ByteOrder::little);
        missing = raw == std::numeric_limits<std::int32_t>::min();
        value = raw;
        break;
      }
      case 7:
        value = BinaryView::decode<double>(source, ByteOrder::little);
        break;
      default:
        value = BinaryView::decode<float>(source, ByteOrder::little);
    }
    values[k] = missing || !std::isfinite(value) ? std::numeric_limits<Real>::quiet_NaN() : value * dz;
  }
  return make_topography(nx, ny, dx, dy, std::move(values));
}

}  // namespace

bool looks_like_sdf(std::string_view bytes) {
  return bytes.starts_with("aISO-1.0") || bytes.starts_with("bISO-1.0") || bytes.starts_with("aBCR-1.0") ||
         bytes.starts_with("bBCR-1.0");
}

RawTopography read_sdf(const fs::path& path, std::string_view bytes) {
  if (!looks_like_sdf(bytes))
    throw InputError(path, 0, "wrong magic: an SDF file begins with aISO-1.0 (ASCII) or bISO-1.0 (binary)");
  return bytes.front() == 'a' ? read_ascii(path, bytes) : read_binary(path, bytes);
}

}  // namespace contactbench::formats
