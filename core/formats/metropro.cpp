// Zygo MetroPro (.dat), docs/formats.md "metropro": a big-endian header (834 bytes for header formats 1 and
// 2, 4096 for format 3) whose first four bytes are the magic, then the intensity block, then the phase block
// of int32 counts with x fastest. Height = counts * S * O * lambda / R with S the interferometric scale
// factor, O the obliquity factor, lambda the wavelength [m] and R the phase resolution (4096, 32768 or 131072
// by the phase_res code 0, 1, 2), negated when the sign flag is set. Counts >= 2147483640 mark no data.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"

namespace contactbench::formats {

namespace {

constexpr std::int32_t no_data_threshold = 2147483640;

}  // namespace

bool looks_like_metropro(std::string_view bytes) {
  return bytes.size() >= 4 && static_cast<unsigned char>(bytes[0]) == 0x88 &&
         static_cast<unsigned char>(bytes[1]) == 0x1b && static_cast<unsigned char>(bytes[2]) == 0x03 &&
         (bytes[3] == 0x6f || bytes[3] == 0x70 || bytes[3] == 0x71);
}

RawTopography read_metropro(const std::filesystem::path& path, std::string_view bytes) {
  const BinaryView view(path, bytes);
  if (!looks_like_metropro(bytes))
    throw InputError(path, 0, "wrong magic: a MetroPro file begins with 88 1b 03 6f, 70 or 71");
  constexpr ByteOrder big = ByteOrder::big;
  const auto header_size = view.read<std::uint32_t>(6, big, "MetroPro header size");
  const std::uint32_t expected_header = bytes[3] == 0x71 ? 4096 : 834;
  if (header_size != expected_header)
    throw InputError(path, 0,
                     "MetroPro header size " + std::to_string(header_size) + " differs from the " +
                         std::to_string(expected_header) + " bytes its magic implies");
  view.require(0, header_size, "MetroPro header");
  const auto intensity_width = view.read<std::uint16_t>(52, big, "ac_org_width");
  const auto intensity_height = view.read<std::uint16_t>(54, big, "ac_org_height");
  const auto buckets = view.read<std::uint16_t>(56, big, "ac_n_buckets");
  const auto nx = view.read<std::uint16_t>(68, big, "cn_org_width");
  const auto ny = view.read<std::uint16_t>(70, big, "cn_org_height");
  const auto scale_factor = view.read<float>(164, big, "intf_scale_factor");
  const auto wavelength = view.read<float>(168, big, "wavelength_in");
  const auto obliquity = view.read<float>(176, big, "obliquity_factor");
  const auto lateral_resolution = view.read<float>(184, big, "lateral_res");
  const auto phase_code = view.read<std::int16_t>(218, big, "phase_res");
  const auto sign = view.read<std::int16_t>(232, big, "phase sign");

  Real phase_resolution = 0;
  switch (phase_code) {
    case 0:
      phase_resolution = 4096;
      break;
    case 1:
      phase_resolution = 32768;
      break;
    case 2:
      phase_resolution = 131072;
      break;
    default:
      throw InputError(path, 0,
                       "MetroPro phase_res code " + std::to_string(phase_code) + " is not 0, 1 or 2");
  }
  const Real height_per_count = static_cast<Real>(scale_factor) * static_cast<Real>(obliquity) *
                                static_cast<Real>(wavelength) / phase_resolution * (sign != 0 ? -1.0 : 1.0);
  if (!(std::isfinite(height_per_count) && height_per_count != 0))
    throw InputError(
        path, 0, "MetroPro height scale (scale factor x obliquity x wavelength) is not finite and non-zero");
  if (!(std::isfinite(lateral_resolution) && lateral_resolution > 0))
    throw InputError(path, 0, "MetroPro lateral resolution must be > 0");

  const std::uint64_t intensity_bytes = 2ull * buckets * intensity_width * intensity_height;
  const std::uint64_t phase_bytes = grid_bytes(path, nx, ny, 4, "MetroPro phase block");
  const std::string_view data = view.slice(header_size + intensity_bytes, phase_bytes, "MetroPro phase data");

  Channel channel = make_channel("phase height", true, "m", nx, ny);
  channel.lx = static_cast<Real>(lateral_resolution) * nx;
  channel.ly = static_cast<Real>(lateral_resolution) * ny;
  allocate_values(path, channel);
  for (std::size_t k = 0; k < channel.values.size(); ++k) {
    const auto counts = BinaryView::decode<std::int32_t>(data.data() + 4 * k, big);
    channel.values[k] =
        counts >= no_data_threshold ? std::numeric_limits<Real>::quiet_NaN() : counts * height_per_count;
  }
  RawTopography topography;
  topography.channels.push_back(std::move(channel));
  return topography;
}

}  // namespace contactbench::formats
