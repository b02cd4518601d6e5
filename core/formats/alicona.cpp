// Alicona Imaging .al3d, docs/formats.md "al3d": the magic "AliconaImaging\0\r\n", then 52-byte tag records
// (key 20 bytes, value 30 bytes, both NUL-padded, then CR LF): Version, TagCount (the number of records that
// follow), then Cols (nx), Rows (ny), PixelSizeXMeter, PixelSizeYMeter, DepthImageOffset, InvalidPixelValue
// and others. The depth image at DepthImageOffset is float32 little-endian heights in metres, row by row
// with x fastest, each row padded to a multiple of 8 bytes; a value equal to InvalidPixelValue, or NaN, is an
// invalid point. Rows are kept in the file's order. Facts from Gwyddion's alicona.c as SurfaceTopography's
// AL3D.py cites it, checked against al3d-1.al3d.
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view al3d_magic{"AliconaImaging\0\r\n", 17};
constexpr std::size_t tag_size = 52;
// Real files carry about twenty tags; a corrupt count must not make the loop run for ever.
constexpr long long max_tags = 4096;

using Tags = std::map<std::string, std::string>;

const std::string& tag(const fs::path& path, const Tags& tags, const std::string& key) {
  const auto found = tags.find(key);
  if (found == tags.end()) throw InputError(path, 0, "the .al3d header has no tag " + key);
  return found->second;
}

Real number(const fs::path& path, const Tags& tags, const std::string& key) {
  const std::optional<Real> value = parse_real(tag(path, tags, key));
  if (!value || !std::isfinite(*value))
    throw InputError(
        path, 0,
        "the .al3d tag " + key + " is " + formats::quoted(tag(path, tags, key)) + ", not a finite number");
  return *value;
}

long long whole(const fs::path& path, const Tags& tags, const std::string& key) {
  const Real value = number(path, tags, key);
  if (value < 0 || value != std::floor(value) || value > 1e15)
    throw InputError(
        path, 0, "the .al3d tag " + key + " is " + formats::quoted(tag(path, tags, key)) + ", not a count");
  return static_cast<long long>(value);
}

}  // namespace

bool looks_like_alicona(std::string_view bytes) {
  return bytes.starts_with(al3d_magic);
}

RawTopography read_alicona(const fs::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_alicona(bytes)) throw InputError(path, 0, "wrong magic for an Alicona .al3d file");
  Tags tags;
  const auto read_tag = [&](std::uint64_t index) {
    const std::uint64_t offset = al3d_magic.size() + index * tag_size;
    const std::string key = view.text(offset, 20, "an .al3d tag key");
    const std::string value = view.text(offset + 20, 30, "the .al3d tag " + key);
    if (view.slice(offset + 50, 2, "the .al3d tag " + key) != "\r\n")
      throw InputError(path, 0, "corrupt .al3d: the tag " + key + " does not end in CR LF");
    tags[key] = value;
    return key;
  };
  if (read_tag(0) != "Version" || read_tag(1) != "TagCount")
    throw InputError(path, 0, "corrupt .al3d: the first two tags must be Version and TagCount");
  const long long count = whole(path, tags, "TagCount");
  if (count > max_tags)
    throw InputError(path, 0, "corrupt .al3d: TagCount " + std::to_string(count) + " is absurd");
  for (long long k = 0; k < count; ++k)
    read_tag(static_cast<std::uint64_t>(2 + k));

  const long long nx = whole(path, tags, "Cols"), ny = whole(path, tags, "Rows");
  grid_bytes(path, nx, ny, 4, "the .al3d depth image (Cols x Rows)");
  const Real dx = number(path, tags, "PixelSizeXMeter"), dy = number(path, tags, "PixelSizeYMeter");
  if (!(dx > 0) || !(dy > 0))
    throw InputError(path, 0, "the .al3d PixelSizeXMeter and PixelSizeYMeter must be > 0");
  const auto invalid = static_cast<float>(number(path, tags, "InvalidPixelValue"));
  const auto offset = static_cast<std::uint64_t>(whole(path, tags, "DepthImageOffset"));
  const std::uint64_t stride = (static_cast<std::uint64_t>(nx) * 4 + 7) / 8 * 8;
  view.require(offset, stride * static_cast<std::uint64_t>(ny), "the .al3d depth image");

  Channel channel = make_channel("depth", true, "m", nx, ny);
  channel.lx = dx * static_cast<Real>(nx);
  channel.ly = dy * static_cast<Real>(ny);
  allocate_values(path, channel);
  for (long long y = 0; y < ny; ++y)
    for (long long x = 0; x < nx; ++x) {
      const float value = BinaryView::decode<float>(
          bytes.data() + offset + static_cast<std::uint64_t>(y) * stride + 4 * x, ByteOrder::little);
      channel.values[static_cast<std::size_t>(y * nx + x)] = value == invalid || std::isnan(value)
                                                                 ? std::numeric_limits<Real>::quiet_NaN()
                                                                 : static_cast<Real>(value);
    }
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats
