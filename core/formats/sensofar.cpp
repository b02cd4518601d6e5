// Sensofar confocal/interferometric (.plu), docs/formats.md "sensofar": a packed little-endian header with no
// magic (date 128 bytes, time, comment 256 bytes, then ny, nx, the point count and calibration floats with
// the micrometres per pixel in x and y at bytes 404 and 408, the measurement type at 428 which must be 3 for
// a topography, the number of layers at 489), then per layer ny, nx (uint32) and ny x nx float32 heights in
// micrometres with x fastest. 1000001 marks an unmeasured point.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

constexpr float undefined_marker = 1000001.0f;
constexpr std::uint32_t topography_type = 3;
constexpr std::uint64_t first_layer = 500;

}  // namespace

// No magic: the header's own consistency is the signature (type 3, one or more layers, the counts at byte 388
// equal to those the first layer repeats at byte 500, and a size that holds them).
bool looks_like_sensofar(std::string_view bytes) {
  if (bytes.size() < first_layer + 8) return false;
  const auto u32 = [&](std::size_t offset) {
    return BinaryView::decode<std::uint32_t>(bytes.data() + offset, ByteOrder::little);
  };
  return u32(428) == topography_type && bytes[489] != 0 && u32(388) == u32(500) && u32(392) == u32(504) &&
         u32(388) > 0 && u32(392) > 0;
}

RawTopography read_sensofar(const std::filesystem::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  constexpr ByteOrder little = ByteOrder::little;
  view.require(0, first_layer, "Sensofar header");
  const auto type = view.read<std::uint32_t>(428, little, "measurement type");
  if (type != topography_type)
    throw InputError(path, 0,
                     "Sensofar measurement type " + std::to_string(type) +
                         " is not 3 (topography): a profile or "
                         "an unknown measurement, or not a .plu file");
  const auto dx_um = view.read<float>(404, little, "micrometres per pixel in x");
  const auto dy_um = view.read<float>(408, little, "micrometres per pixel in y");
  if (!(std::isfinite(dx_um) && dx_um > 0 && std::isfinite(dy_um) && dy_um > 0))
    throw InputError(path, 0, "Sensofar pixel sizes must be finite and > 0");
  const auto layers = view.read<std::uint8_t>(489, little, "number of layers");
  if (layers == 0) throw InputError(path, 0, "the Sensofar header lists no layer");

  RawTopography topography;
  std::uint64_t offset = first_layer;
  for (unsigned layer = 0; layer < layers; ++layer) {
    const std::string name = "layer" + std::to_string(layer);
    const auto ny = view.read<std::uint32_t>(offset, little, name + " ny");
    const auto nx = view.read<std::uint32_t>(offset + 4, little, name + " nx");
    const std::uint64_t size = grid_bytes(path, nx, ny, 4, "Sensofar " + name);
    const std::string_view data = view.slice(offset + 8, size, "Sensofar " + name + " heights");
    Channel channel = make_channel(name, true, "um", nx, ny);
    channel.lx = static_cast<Real>(nx) * dx_um * 1e-6;
    channel.ly = static_cast<Real>(ny) * dy_um * 1e-6;
    allocate_values(path, channel);
    for (std::size_t k = 0; k < channel.values.size(); ++k) {
      const auto value = BinaryView::decode<float>(data.data() + 4 * k, little);
      channel.values[k] = value == undefined_marker || !std::isfinite(value)
                              ? std::numeric_limits<Real>::quiet_NaN()
                              : static_cast<Real>(value) * 1e-6;
    }
    topography.channels.push_back(std::move(channel));
    offset += 8 + size + 8;  // the layer's counts, heights, then its min and max (float32 each)
  }
  return topography;
}

}  // namespace contactbench::formats
