// Wyko / Bruker Vision (.opd), docs/formats.md "wyko": two bytes, then a directory of 24-byte entries (name
// 16 bytes, type int16, length int32, attributes uint16), the first of which is "Directory" itself and whose
// length says how many entries there are; the blocks' contents follow in directory order. A data block
// ("RAW DATA", "RAW_DATA", "OPD", "Raw") begins with nx, ny, the element size (uint16 each), then int16 or
// float32 values stored column by column (y fastest, from the top down). Height = value * wavelength [nm] /
// Mult; pixel size in mm, the y size times Aspect. Invalid: int16 >= 32766, float >= 1e38, NaN or Inf.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

constexpr std::uint64_t entry_size = 24;

struct Block {
  std::string name;
  std::int32_t length = 0;
  std::uint64_t offset = 0;  // where its content begins
};

struct WykoDataBlock {
  std::string name;
  std::uint16_t nx = 0, ny = 0, element_size = 0;
  std::uint64_t data_offset = 0;
};

}  // namespace

bool looks_like_wyko(std::string_view bytes) {
  return bytes.size() >= 11 && bytes.substr(2, 9) == "Directory";
}

RawTopography read_wyko(const std::filesystem::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_wyko(bytes))
    throw InputError(path, 0, "wrong magic: a Wyko .opd file has 'Directory' at byte 2");
  constexpr ByteOrder little = ByteOrder::little;
  const auto directory_length = view.read<std::int32_t>(2 + 18, little, "directory length");
  if (directory_length <= 0 || directory_length % entry_size != 0)
    throw InputError(
        path, 0,
        "Wyko directory length " + std::to_string(directory_length) + " is not a positive multiple of 24");
  const std::uint64_t entries = static_cast<std::uint64_t>(directory_length) / entry_size;
  view.require(2, entries * entry_size, "Wyko directory");

  std::vector<Block> blocks;
  std::uint64_t content = 2 + entries * entry_size;
  for (std::uint64_t k = 1; k < entries; ++k) {
    const std::uint64_t at = 2 + k * entry_size;
    Block block{view.text(at, 16, "block name"), view.read<std::int32_t>(at + 18, little, "block length"),
                content};
    if (block.length > 0) {
      content += static_cast<std::uint64_t>(block.length);
      blocks.push_back(std::move(block));
    }
  }

  if (content > bytes.size())
    throw InputError(path, 0,
                     "truncated or corrupt: the Wyko directory's blocks end at byte " +
                         std::to_string(content) + " but the file has " + std::to_string(bytes.size()) +
                         " bytes");

  Real wavelength_nm = 0;
  Real mult = 1;
  Real aspect = 1;
  Real pixel_mm = 0;
  std::vector<WykoDataBlock> data_blocks;
  for (const Block& block : blocks) {
    const std::string& n = block.name;
    if (n == "RAW DATA" || n == "RAW_DATA" || n == "OPD" || n == "Raw") {
      WykoDataBlock data{n, view.read<std::uint16_t>(block.offset, little, n + " nx"),
                         view.read<std::uint16_t>(block.offset + 2, little, n + " ny"),
                         view.read<std::uint16_t>(block.offset + 4, little, n + " element size"),
                         block.offset + 6};
      if (data.element_size != 2 && data.element_size != 4)
        throw InputError(path, 0,
                         "Wyko block '" + n + "' has " + std::to_string(data.element_size) +
                             "-byte elements; known: 2 (int16) and 4 (float32)");
      const std::uint64_t size =
          grid_bytes(path, data.nx, data.ny, data.element_size, "Wyko block '" + n + "'");
      if (6 + size > static_cast<std::uint64_t>(block.length))
        throw InputError(path, 0,
                         "Wyko block '" + n + "' is " + std::to_string(block.length) + " bytes but its " +
                             std::to_string(data.nx) + " x " + std::to_string(data.ny) + " points need " +
                             std::to_string(6 + size));
      view.require(data.data_offset, size, "Wyko block '" + n + "' data");
      data_blocks.push_back(data);
    } else if (n == "Wavelength") {
      wavelength_nm = view.read<float>(block.offset, little, "Wavelength");
    } else if (n == "Mult") {
      mult = view.read<std::uint16_t>(block.offset, little, "Mult");
    } else if (n == "Aspect") {
      aspect = view.read<float>(block.offset, little, "Aspect");
    } else if (n == "Pixel_size") {
      pixel_mm = view.read<float>(block.offset, little, "Pixel_size");
    }
  }
  if (data_blocks.empty())
    throw InputError(path, 0, "the Wyko file has no data block (RAW DATA, OPD or Raw)");
  if (!(std::isfinite(wavelength_nm) && wavelength_nm > 0) || !(mult > 0))
    throw InputError(path, 0, "the Wyko file has no valid Wavelength (> 0) and Mult (> 0)");
  if (!(std::isfinite(pixel_mm) && pixel_mm > 0) || !(std::isfinite(aspect) && aspect > 0))
    throw InputError(path, 0, "the Wyko file has no valid Pixel_size (> 0) and Aspect (> 0)");

  RawTopography topography;
  const Real metres_per_unit = wavelength_nm / mult * 1e-9;
  for (const WykoDataBlock& data : data_blocks) {
    const Index nx = data.nx;
    const Index ny = data.ny;
    Channel channel = make_channel(data.name, true, "m", nx, ny);
    channel.lx = static_cast<Real>(nx) * pixel_mm * 1e-3;
    channel.ly = static_cast<Real>(ny) * pixel_mm * aspect * 1e-3;
    allocate_values(path, channel);
    // Stored column by column, kept row by row: the transpose goes tile by tile so that the tile's columns
    // and rows both stay in cache (column by column it was among the slowest reads of
    // results/bench/formats_read.md).
    constexpr Index tile = 64;
    for (Index x0 = 0; x0 < nx; x0 += tile)
      for (Index s0 = 0; s0 < ny; s0 += tile)
        for (Index x = x0; x < std::min(nx, x0 + tile); ++x)
          for (Index stored = s0; stored < std::min(ny, s0 + tile); ++stored) {
            const char* source = view.bytes().data() + data.data_offset +
                                 static_cast<std::uint64_t>(x * ny + stored) * data.element_size;
            Real value = 0;
            bool invalid = false;
            if (data.element_size == 2) {
              const auto raw = BinaryView::decode<std::int16_t>(source, little);
              invalid = raw >= 32766;
              value = raw;
            } else {
              const auto raw = BinaryView::decode<float>(source, little);
              invalid = !std::isfinite(raw) || raw >= 1e38f;
              value = raw;
            }
            // Stored from the top down: the first value of a column is the largest y.
            channel.values[static_cast<std::size_t>((ny - 1 - stored) * nx + x)] =
                invalid ? std::numeric_limits<Real>::quiet_NaN() : value * metres_per_unit;
          }
    topography.channels.push_back(std::move(channel));
  }
  return topography;
}

}  // namespace contactbench::formats
