// Digital Surf (.sur), docs/formats.md "digital-surf": a 512-byte little-endian header beginning with
// "DIGITAL SURF": the non-measured-points flag at byte 86, bits per point (16 or 32) at 98, zmin and zmax at
// 100 and 104, nx and ny at 108 and 112, the point count at 116, the x and y spacings and the z scale
// (float32) at 120, 124, 128, their unit strings (16 bytes each) from 132, the comment and private-zone sizes
// at 334 and 336, then the comment, the private zone and the integer data, x fastest.
// Height = value * z scale in the z unit. Non-measured points: when the flag is set they hold zmin - 2 (a
// value below the stated range), and this reader marks them invalid.
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

constexpr std::string_view magic = "DIGITAL SURF";
constexpr std::uint64_t header_size = 512;

std::optional<Real> digital_surf_length_unit(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "\xb5m" || unit == "um" || unit == "\xc2\xb5m") return 1e-6;
  if (unit == "nm") return 1e-9;
  if (unit == "pm") return 1e-12;
  return std::nullopt;
}

Real metres(const BinaryView& view, std::uint64_t offset, const char* what) {
  const std::string unit = view.text(offset, 16, what);
  const std::optional<Real> factor = digital_surf_length_unit(unit);
  if (!factor)
    throw InputError(
        view.path(), 0,
        std::string("Digital Surf ") + what + " '" + unit + "' is not a length unit (m, mm, um, nm, pm)");
  return *factor;
}

}  // namespace

bool looks_like_digital_surf(std::string_view bytes) {
  return bytes.starts_with(magic);
}

RawTopography read_digital_surf(const std::filesystem::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_digital_surf(bytes))
    throw InputError(path, 0, "wrong magic: a .sur file begins with 'DIGITAL SURF'");
  constexpr ByteOrder little = ByteOrder::little;
  view.require(0, header_size, "Digital Surf header");
  const auto objects = view.read<std::uint16_t>(14, little, "number of objects");
  if (objects > 1)
    throw InputError(path, 0, "Digital Surf series of " + std::to_string(objects) + " objects are not read");
  const auto non_measured_flag = view.read<std::uint16_t>(86, little, "non-measured points flag");
  const auto bits = view.read<std::uint16_t>(98, little, "bits per point");
  if (bits != 16 && bits != 32)
    throw InputError(path, 0,
                     "Digital Surf data of " + std::to_string(bits) + " bits per point; known: 16 and 32");
  const auto zmin = view.read<std::int32_t>(100, little, "zmin");
  const auto nx = view.read<std::int32_t>(108, little, "nx");
  const auto ny = view.read<std::int32_t>(112, little, "ny");
  const auto points = view.read<std::uint32_t>(116, little, "number of points");
  const auto dx = view.read<float>(120, little, "x spacing");
  const auto dy = view.read<float>(124, little, "y spacing");
  const auto dz = view.read<float>(128, little, "z scale");
  const std::uint64_t item = bits / 8;
  const std::uint64_t size = grid_bytes(path, nx, ny, item, "Digital Surf header");
  if (static_cast<std::uint64_t>(points) != static_cast<std::uint64_t>(nx) * static_cast<std::uint64_t>(ny))
    throw InputError(path, 0,
                     "Digital Surf header gives " + std::to_string(points) + " points for a " +
                         std::to_string(nx) + " x " + std::to_string(ny) + " grid");
  if (!(std::isfinite(dx) && dx > 0 && std::isfinite(dy) && dy > 0 && std::isfinite(dz) && dz != 0))
    throw InputError(path, 0, "Digital Surf spacings must be > 0 and the z scale finite and non-zero");
  // Spacing units are the 'delta' units at 180 (x), 196 (y), 212 (z).
  const Real x_unit = metres(view, 180, "x spacing unit");
  const Real y_unit = metres(view, 196, "y spacing unit");
  const Real z_unit = metres(view, 212, "z unit");
  const auto comment_size = view.read<std::uint16_t>(334, little, "comment size");
  const auto private_size = view.read<std::uint16_t>(336, little, "private zone size");
  const std::string_view data =
      view.slice(header_size + comment_size + private_size, size, "Digital Surf data");

  const std::int64_t marker = static_cast<std::int64_t>(zmin) - 2;
  Channel channel = make_channel("height", true, view.text(212, 16, "z unit"), nx, ny);
  channel.lx = static_cast<Real>(dx) * x_unit * nx;
  channel.ly = static_cast<Real>(dy) * y_unit * ny;
  allocate_values(path, channel);
  const Real scale = static_cast<Real>(dz) * z_unit;
  for (std::size_t k = 0; k < channel.values.size(); ++k) {
    const char* source = data.data() + k * item;
    const std::int64_t value = bits == 16 ? BinaryView::decode<std::int16_t>(source, little)
                                          : BinaryView::decode<std::int32_t>(source, little);
    channel.values[k] = non_measured_flag != 0 && value == marker ? std::numeric_limits<Real>::quiet_NaN()
                                                                  : static_cast<Real>(value) * scale;
  }
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats
