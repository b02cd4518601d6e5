// Agilent / Keysight PicoView .mi images, docs/formats.md "mi": a text header of lines whose first 14
// characters are the key and the rest the value (fileType Image, xPixels, yPixels, xLength, yLength in
// metres, scanUp), then one group of lines per buffer starting at bufferLabel (direction, bufferRange,
// bufferUnit), ended by the line "data          BINARY_32". The buffers follow, in header order, each xPixels
// * yPixels int32 little-endian values, x fastest; value = raw / 2^31 * bufferRange in bufferUnit. With
// scanUp TRUE the file's last line is y = 0 (the lines are reversed), as SurfaceTopography reads it. Facts
// from SurfaceTopography's MI.py, checked against mi-1.mi.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t key_width = 14;

struct Buffer {
  std::string label, direction, unit;
  std::optional<Real> range;
};

Real number(const fs::path& path, const std::string& key, const std::optional<std::string>& text) {
  if (!text) throw InputError(path, 0, "the .mi header has no " + key);
  const std::optional<Real> value = parse_real(*text);
  if (!value || !std::isfinite(*value))
    throw InputError(path, 0,
                     "the .mi header's " + key + " is " + formats::quoted(*text) + ", not a finite number");
  return *value;
}

}  // namespace

bool looks_like_agilent_mi(std::string_view bytes) {
  return bytes.starts_with("fileType      ");
}

RawTopography read_agilent_mi(const fs::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_agilent_mi(bytes)) throw InputError(path, 0, "wrong magic for an Agilent .mi file");
  std::optional<std::string> file_type, x_pixels, y_pixels, x_length, y_length, scan_up;
  std::vector<Buffer> buffers;
  std::size_t start = 0;
  std::optional<std::size_t> data_start;
  while (start < bytes.size() && !data_start) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string_view::npos) break;
    const std::string_view line = bytes.substr(start, end - start);
    start = end + 1;
    const std::string key(trim(line.substr(0, std::min(key_width, line.size())), is_space));
    const std::string value(
        trim(line.size() > key_width ? line.substr(key_width) : std::string_view(), is_space));
    if (key == "data") {
      if (value != "BINARY_32")
        throw InputError(path, 0, "the .mi data are '" + value + "'; only BINARY_32 is read");
      data_start = start;
    } else if (key == "fileType") {
      file_type = value;
    } else if (key == "xPixels") {
      x_pixels = value;
    } else if (key == "yPixels") {
      y_pixels = value;
    } else if (key == "xLength") {
      x_length = value;
    } else if (key == "yLength") {
      y_length = value;
    } else if (key == "scanUp") {
      scan_up = value;
    } else if (key == "bufferLabel") {
      buffers.push_back(Buffer{value, "", "", std::nullopt});
    } else if (!buffers.empty() && key == "direction") {
      buffers.back().direction = value;
    } else if (!buffers.empty() && key == "bufferUnit") {
      buffers.back().unit = value;
    } else if (!buffers.empty() && key == "bufferRange") {
      buffers.back().range = number(path, "bufferRange of " + buffers.back().label, value);
    }
  }
  if (!data_start) throw InputError(path, 0, "truncated or corrupt: the .mi header has no 'data' line");
  if (file_type != "Image")
    throw InputError(path, 0,
                     "the .mi file is of type '" + file_type.value_or("") + "'; only Image files are read");
  if (buffers.empty()) throw InputError(path, 0, "the .mi header names no buffer (bufferLabel)");
  const Real nx_value = number(path, "xPixels", x_pixels), ny_value = number(path, "yPixels", y_pixels);
  const auto nx = static_cast<long long>(nx_value), ny = static_cast<long long>(ny_value);
  if (static_cast<Real>(nx) != nx_value || static_cast<Real>(ny) != ny_value)
    throw InputError(path, 0, "the .mi xPixels and yPixels must be whole numbers");
  const std::uint64_t block = grid_bytes(path, nx, ny, 4, "the .mi image (xPixels x yPixels)");
  const Real lx = number(path, "xLength", x_length), ly = number(path, "yLength", y_length);
  const bool reversed = scan_up == "TRUE";

  RawTopography topography;
  std::uint64_t offset = *data_start;
  for (const Buffer& buffer : buffers) {
    int same_label = 0;
    for (const Buffer& other : buffers)
      same_label += other.label == buffer.label;
    std::string direction = buffer.direction;
    for (char& c : direction)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::string name = same_label > 1 ? buffer.label + " " + direction : buffer.label;
    const std::optional<Real> metres = length_unit_in_metres(buffer.unit);
    Channel channel = make_channel(name, metres.has_value(), buffer.unit, nx, ny);
    channel.lx = lx;
    channel.ly = ly;
    const std::string_view data = view.slice(offset, block, "the .mi buffer " + name);
    offset += block;
    if (channel.is_height) {
      if (!buffer.range || *buffer.range == 0)
        throw InputError(path, 0, "the .mi buffer " + name + " has no bufferRange other than 0");
      const Real scale = *buffer.range / 2147483648.0 * *metres;
      allocate_values(path, channel);
      for (long long y = 0; y < ny; ++y) {
        const long long line = reversed ? ny - 1 - y : y;
        for (long long x = 0; x < nx; ++x)
          channel.values[static_cast<std::size_t>(y * nx + x)] =
              static_cast<Real>(
                  BinaryView::decode<std::int32_t>(data.data() + 4 * (line * nx + x), ByteOrder::little)) *
              scale;
      }
    }
    topography.channels.push_back(std::move(channel));
  }
  return topography;
}

}  // namespace contactbench::formats
