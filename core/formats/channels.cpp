#include "contactbench/core/formats/channels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/height_unit.hpp"
#include "contactbench/core/formats/lateral_sizes.hpp"

namespace contactbench::formats {

namespace fs = std::filesystem;

namespace {

std::string channel_list(const RawTopography& raw) {
  std::string list;
  for (std::size_t k = 0; k < raw.channels.size(); ++k) {
    const Channel& channel = raw.channels[k];
    if (k > 0) list += ", ";
    list += std::to_string(k) + " '" + channel.name + "'" + (channel.is_height ? "" : " (not a height)");
  }
  return list;
}

std::size_t select_channel(const fs::path& path, const RawTopography& raw,
                           const std::optional<std::string>& wanted) {
  if (!wanted) {
    for (std::size_t k = 0; k < raw.channels.size(); ++k)
      if (raw.channels[k].is_height) return k;
    throw InputError(path, 0, "no height channel; the file's channels: " + channel_list(raw));
  }
  std::optional<std::size_t> chosen;
  const bool digits = !wanted->empty() && std::all_of(wanted->begin(), wanted->end(),
                                                      [](char c) { return c >= '0' && c <= '9'; });
  if (digits && wanted->size() < 9) {
    const std::size_t index = std::stoul(*wanted);
    if (index < raw.channels.size()) chosen = index;
  } else {
    for (std::size_t k = 0; k < raw.channels.size() && !chosen; ++k)
      if (raw.channels[k].name == *wanted) chosen = k;
  }
  if (!chosen)
    throw InputError(path, 0, "unknown channel '" + *wanted + "'; the file's channels: " + channel_list(raw));
  if (!raw.channels[*chosen].is_height)
    throw InputError(
        path, 0,
        "channel '" + *wanted + "' does not hold heights; the file's channels: " + channel_list(raw));
  return *chosen;
}

}  // namespace

TopographyReading reading_from_channels(const fs::path& path, RawTopography raw, TopographyFormat format,
                                        const TopographyReadOptions& options) {
  const std::size_t index = select_channel(path, raw, options.channel);
  Channel& channel = raw.channels[index];

  // Inf is an invalid point as NaN is (docs/formats.md "invalid points"), whatever the format; counted in
  // the same pass (a crop below counts again, in its rectangle).
  Index invalid = 0;
  for (Real& value : channel.values)
    if (!std::isfinite(value)) {
      value = std::numeric_limits<Real>::quiet_NaN();
      ++invalid;
    }
  std::string unit = channel.unit;
  if (!format_carries_unit(format)) {
    if (options.unit) {
      const Real per_metre = given_units_per_metre(path, *options.unit);
      for (Real& value : channel.values)
        value /= per_metre;
      // A point list's coordinates are in the same unit as its heights.
      if (channel.lx) *channel.lx /= per_metre;
      if (channel.ly) *channel.ly /= per_metre;
      unit = *options.unit;
    } else {
      unit = "m";
    }
  } else if (options.unit) {
    throw InputError(path, 0,
                     "a " + std::string(to_string(format)) + " file states its own unit ('" + channel.unit +
                         "'); a unit (--unit, unit = \"...\") is only for files that state none (npy, plain "
                         "or CSV matrices, x y z point lists)");
  }

  Real lx = 0;
  Real ly = 0;
  if (channel.lx && channel.ly) {
    check_lateral_size(path, 0, "lx", *channel.lx);
    check_lateral_size(path, 0, "ly", *channel.ly);
    check_agrees(path, 0, "lx", *channel.lx, options.lx);
    check_agrees(path, 0, "ly", *channel.ly, options.ly);
    lx = *channel.lx;
    ly = *channel.ly;
  } else {
    if (!options.lx)
      throw InputError(path, 0,
                       "no lateral size: a " + std::string(to_string(format)) +
                           " file carries none, so the caller must give it (--size)");
    check_lateral_size(path, 0, "the given lx", *options.lx);
    lx = *options.lx;
    ly = options.ly.value_or(lx * static_cast<Real>(channel.ny) / static_cast<Real>(channel.nx));
    check_lateral_size(path, 0, "ly", ly);
  }

  // After the sizes, so that a missing --size is named first; before anything is filled.
  if (!format_carries_unit(format) && !options.unit)
    check_plausible_as_metres(path, channel.values, std::string(to_string(format)));

  std::string crop = "none";
  if (options.crop) {
    Index nx = channel.nx, ny = channel.ny;
    const formats::CropResult kept = crop_values(path, channel.values, nx, ny, lx, ly, *options.crop);
    crop = to_string(*options.crop) + " (columns " + std::to_string(kept.x0) + " to " +
           std::to_string(kept.x0 + nx - 1) + ", rows " + std::to_string(kept.y0) + " to " +
           std::to_string(kept.y0 + ny - 1) + ")";
    channel.nx = nx;
    channel.ny = ny;
    invalid = static_cast<Index>(
        std::count_if(channel.values.begin(), channel.values.end(), [](Real v) { return std::isnan(v); }));
  }
  if (invalid == static_cast<Index>(channel.values.size()))
    throw InputError(path, 0,
                     "all " + std::to_string(invalid) + " points of channel '" + channel.name +
                         "' are invalid (not measured): there is no surface to read");
  if (invalid > 0 && options.fill == FillMethod::none)
    throw InputError(path, 0,
                     std::to_string(invalid) + " of " + std::to_string(channel.values.size()) +
                         " points of channel '" + channel.name +
                         "' are invalid (not measured); they are never used as heights: choose fill = "
                         "\"harmonic\" or \"mean\" (--fill) to fill them");
  // Without invalid points every value is finite (Inf became NaN above) and there is nothing to fill: the two
  // passes below would only re-read the grid (results/bench/formats_read.md).
  if (invalid > 0) {
    try {
      fill_invalid_points(channel.values, channel.nx, channel.ny, options.fill);
    } catch (const InputError&) {
      throw;
    } catch (const Error& error) {
      throw InputError(path, 0, "channel '" + channel.name + "': " + error.what());
    }
    for (const Real value : channel.values)
      if (!std::isfinite(value))
        throw InputError(path, 0,
                         "channel '" + channel.name + "' holds a height that is not finite after scaling");
  }

  // A part of a periodic surface does not repeat; the caller may still say it does.
  const Grid grid{channel.nx, channel.ny, lx, ly,
                  options.periodic.value_or(options.crop ? false : raw.periodic)};
  HeightMap heights = Eigen::Map<const HeightMap>(channel.values.data(), channel.ny, channel.nx);
  align_rows(heights, options.align_rows);
  level_heights(heights, grid, options.level);
  std::vector<std::string> names;
  for (const Channel& c : raw.channels)
    names.push_back(c.name);
  return TopographyReading{Surface(grid, std::move(heights)),
                           format,
                           channel.name,
                           std::move(names),
                           invalid,
                           options.fill,
                           options.level,
                           unit,
                           crop,
                           options.align_rows};
}

}  // namespace contactbench::formats
