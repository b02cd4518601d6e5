// Bruker / Digital Instruments Nanoscope (.di, .spm, .001 ...), docs/formats.md "nanoscope": a text header of
// "\*Section" and "\key: value" lines ending at "\*File list end", one "\*Ciao image list" section per
// channel giving its data offset, samples per line (nx), number of lines (ny), bytes per pixel (2 or 4,
// little-endian signed integers) and scan size; the lines are stored from the top of the image down, so the
// first stored line is the largest y. Height = counts * (hard scale [V] / 65536) * sensitivity [length/V],
// with a further 1/65536 for 4-byte data (they carry 16 more bits of resolution, not of range).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/declared_memory.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/formats/text_tokens.hpp"

namespace contactbench::formats {

namespace {

namespace fs = std::filesystem;

using Section = std::map<std::string, std::string>;

std::string lower(std::string_view text) {
  std::string result(text);
  for (char& c : result)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return result;
}

std::string_view strip(std::string_view text) {
  return trim(text, is_space);
}

// The values of a header entry ("500 500 nm") are separated by spaces alone.
std::vector<std::string_view> tokens(std::string_view text) {
  return split_tokens(text, [](char c) { return c == ' '; });
}

std::optional<Real> number(std::string_view text) {
  Real value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Metres per unit for the length units Nanoscope headers use ('~m' is its spelling of micrometre).
std::optional<Real> nanoscope_length_unit(std::string_view unit) {
  if (unit == "m") return 1.0;
  if (unit == "mm") return 1e-3;
  if (unit == "~m" || unit == "um" || unit == "\xb5m" || unit == "\xc2\xb5m") return 1e-6;
  if (unit == "nm") return 1e-9;
  if (unit == "pm") return 1e-12;
  return std::nullopt;
}

std::optional<Real> voltage_unit(std::string_view unit) {
  if (unit == "V") return 1.0;
  if (unit == "mV") return 1e-3;
  return std::nullopt;
}

const std::string& entry(const fs::path& path, const Section& section, const std::string& key, int channel) {
  const auto found = section.find(key);
  if (found == section.end())
    throw InputError(path, 0,
                     "Nanoscope image section " + std::to_string(channel) + " has no '\\" + key + ":' line");
  return found->second;
}

long long whole(const fs::path& path, const std::string& text, const std::string& key, int channel) {
  long long value = 0;
  const std::string_view trimmed = strip(text);
  const auto [end, error] = std::from_chars(trimmed.data(), trimmed.data() + trimmed.size(), value);
  if (error != std::errc() || end != trimmed.data() + trimmed.size() || value < 0)
    throw InputError(path, 0,
                     "Nanoscope image section " + std::to_string(channel) + ": '" + key + "' is '" + text +
                         "', not a whole number >= 0");
  return value;
}

}  // namespace

bool looks_like_nanoscope(std::string_view bytes) {
  return bytes.starts_with("\\*File list") || bytes.starts_with("?*File list");
}

RawTopography read_nanoscope(const fs::path& path, std::string_view bytes) {
  if (!looks_like_nanoscope(bytes))
    throw InputError(path, 0, "wrong magic: a Nanoscope file begins with '\\*File list'");
  // The header: lines up to "\*File list end".
  std::vector<std::pair<std::string, Section>> sections;
  bool ended = false;
  std::size_t start = 0;
  while (start < bytes.size() && !ended) {
    std::size_t end = bytes.find('\n', start);
    if (end == std::string_view::npos) end = bytes.size();
    const std::string_view line = strip(bytes.substr(start, end - start));
    start = end + 1;
    if (line.empty()) continue;
    if (line.starts_with("\\*")) {
      const std::string name = lower(line.substr(2));
      if (name == "file list end") {
        ended = true;
      } else {
        sections.push_back({name, {}});
      }
    } else if (line.starts_with('\\') && !sections.empty()) {
      const std::string_view body = line.substr(1);
      const std::size_t colon = body.find(": ");
      const std::string key = lower(strip(colon == std::string_view::npos ? body : body.substr(0, colon)));
      const std::string value(colon == std::string_view::npos ? std::string_view()
                                                              : strip(body.substr(colon + 2)));
      sections.back().second.emplace(key, value);
    } else if (line.front() == '\x1a') {
      break;  // end-of-text mark before the binary data
    } else {
      throw InputError(
          path, 0,
          "Nanoscope header line '" + std::string(line.substr(0, 40)) + "' does not begin with '\\'");
    }
  }
  if (!ended) throw InputError(path, 0, "truncated Nanoscope header: no '\\*File list end' line");

  Section scanner;
  for (const auto& [name, section] : sections)
    if (name == "scanner list" || name == "ciao scan list") scanner.insert(section.begin(), section.end());

  RawTopography topography;
  int index = 0;
  for (const auto& [name, section] : sections) {
    if (name != "ciao image list") continue;
    const int channel_index = index++;
    // Channel name: '@2:image data: S [Height] "Height"' -> Height.
    std::string channel_name = "channel " + std::to_string(channel_index);
    if (const auto found = section.find("@2:image data"); found != section.end()) {
      const std::size_t open = found->second.find('[');
      const std::size_t close = found->second.find(']', open == std::string::npos ? 0 : open);
      if (open != std::string::npos && close != std::string::npos)
        channel_name = found->second.substr(open + 1, close - open - 1);
    }
    const long long offset =
        whole(path, entry(path, section, "data offset", channel_index), "Data offset", channel_index);
    const long long length =
        whole(path, entry(path, section, "data length", channel_index), "Data length", channel_index);
    const long long pixel_bytes =
        whole(path, entry(path, section, "bytes/pixel", channel_index), "Bytes/pixel", channel_index);
    const long long nx =
        whole(path, entry(path, section, "samps/line", channel_index), "Samps/line", channel_index);
    const long long ny =
        whole(path, entry(path, section, "number of lines", channel_index), "Number of lines", channel_index);
    if (pixel_bytes != 2 && pixel_bytes != 4)
      throw InputError(path, 0,
                       "Nanoscope channel '" + channel_name + "' has " + std::to_string(pixel_bytes) +
                           " bytes per pixel; known: 2 and 4");
    const std::uint64_t size = grid_bytes(path, nx, ny, static_cast<std::uint64_t>(pixel_bytes),
                                          "Nanoscope channel '" + channel_name + "'");
    if (size > static_cast<std::uint64_t>(length))
      throw InputError(path, 0,
                       "Nanoscope channel '" + channel_name + "': " + std::to_string(nx) + " x " +
                           std::to_string(ny) + " points need " + std::to_string(size) +
                           " bytes but the data length is " + std::to_string(length));
    if (static_cast<std::uint64_t>(offset) > bytes.size() ||
        size > bytes.size() - static_cast<std::uint64_t>(offset))
      throw InputError(path, 0,
                       "truncated or corrupt: Nanoscope channel '" + channel_name + "' needs bytes " +
                           std::to_string(offset) + " to " +
                           std::to_string(static_cast<std::uint64_t>(offset) + size) + " but the file has " +
                           std::to_string(bytes.size()) + " bytes");

    // Scan size "500 500 nm" (older files give one value for a square scan).
    const std::vector<std::string_view> scan = tokens(entry(path, section, "scan size", channel_index));
    std::optional<Real> sx, sy, lateral_unit;
    if (scan.size() == 3) {
      sx = number(scan[0]);
      sy = number(scan[1]);
      lateral_unit = nanoscope_length_unit(scan[2]);
    } else if (scan.size() == 2) {
      sx = sy = number(scan[0]);
      lateral_unit = nanoscope_length_unit(scan[1]);
    }
    if (!sx || !sy || !lateral_unit || !(*sx > 0) || !(*sy > 0))
      throw InputError(path, 0,
                       "Nanoscope channel '" + channel_name + "': scan size '" +
                           entry(path, section, "scan size", channel_index) +
                           "' is not two sizes > 0 and a length unit (m, mm, ~m, um, nm, pm)");

    Channel channel = make_channel(channel_name, false, "", static_cast<Index>(nx), static_cast<Index>(ny));
    channel.lx = *sx * *lateral_unit;
    channel.ly = *sy * *lateral_unit;

    // Z scale: 'V [Sens. Zsens] (0.005035400 V/LSB) 2.910461 V': the bracket names the sensitivity key, the
    // value after the parenthesis is the hard scale in volts for the full 16-bit range.
    const std::string& z_scale = entry(path, section, "@2:z scale", channel_index);
    const std::size_t open = z_scale.find('[');
    const std::size_t close = z_scale.find(']');
    const std::size_t paren = z_scale.rfind(')');
    std::optional<Real> metres_per_count;
    if (open != std::string::npos && close != std::string::npos && close > open &&
        paren != std::string::npos) {
      const std::string quantity = lower(z_scale.substr(open + 1, close - open - 1));
      const std::vector<std::string_view> hard = tokens(std::string_view(z_scale).substr(paren + 1));
      const auto sensitivity = scanner.find("@" + quantity);
      if (hard.size() == 2 && sensitivity != scanner.end()) {
        const std::vector<std::string_view> soft = tokens(sensitivity->second);
        const std::optional<Real> hard_value = number(hard[0]);
        const std::optional<Real> hard_volts = voltage_unit(hard[1]);
        if (soft.size() == 3 && soft[0] == "V" && hard_value && hard_volts) {
          const std::size_t slash = soft[2].find('/');
          const std::optional<Real> soft_value = number(soft[1]);
          if (slash != std::string_view::npos && soft_value) {
            const std::optional<Real> height_unit = nanoscope_length_unit(soft[2].substr(0, slash));
            const std::optional<Real> per_volt = voltage_unit(soft[2].substr(slash + 1));
            channel.unit = std::string(soft[2].substr(0, slash));
            if (height_unit && per_volt)
              metres_per_count = *hard_value / 65536.0 * (*hard_volts / *per_volt) * *soft_value *
                                 *height_unit * (pixel_bytes == 4 ? 1.0 / 65536.0 : 1.0);
          }
        }
      }
    }
    if (metres_per_count && !(std::isfinite(*metres_per_count) && *metres_per_count != 0))
      throw InputError(
          path, 0,
          "channel '" + channel.name + "': its height scale (@2:Z scale times the sensitivity) is " +
              std::to_string(*metres_per_count) + " m per count; it must be finite and non-zero");
    if (metres_per_count) {
      channel.is_height = true;
      allocate_values(path, channel);
      const char* data = bytes.data() + offset;
      for (long long line = 0; line < ny; ++line)
        for (long long x = 0; x < nx; ++x) {
          const char* source = data + (line * nx + x) * pixel_bytes;
          const Real counts = pixel_bytes == 2 ? BinaryView::decode<std::int16_t>(source, ByteOrder::little)
                                               : BinaryView::decode<std::int32_t>(source, ByteOrder::little);
          // The first stored line is the top of the image (largest y).
          channel.values[static_cast<std::size_t>((ny - 1 - line) * nx + x)] = counts * *metres_per_count;
        }
    }
    topography.channels.push_back(std::move(channel));
  }
  if (topography.channels.empty())
    throw InputError(path, 0, "the Nanoscope header lists no image (no '\\*Ciao image list')");
  return topography;
}

}  // namespace contactbench::formats
