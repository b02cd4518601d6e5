#include "contactbench/app/topography_options.hpp"

#include "contactbench/core/topography_io.hpp"

namespace contactbench {

void TopographyOptions::add_to(CLI::App& command, const std::string& periodic_effect) {
  command
      .add_option("FILE", file,
                  "topography: the project's format, an interferometer or Gwyddion text export, or a plain "
                  "matrix of heights in metres (then --size is needed)")
      ->required();
  // The formats are those of docs/formats.md: .x3p, .sdf, .npy, .dat (MetroPro), .di, .plu, .sur, .opd, .nc
  // and the text exports.
  command.add_option("--size", size, "lateral size along x [m] (for files that carry none)");
  command.add_option("--size-y", size_y, "lateral size along y [m] (default: square pixels)");
  command.add_flag("--periodic", periodic, "treat the surface as periodic (" + periodic_effect + ")");
  command.add_option("--channel", channel,
                     "channel of a multi-channel file, by name or 0-based index (default: the first height "
                     "channel)");
  command
      .add_option("--fill", fill,
                  "invalid (unmeasured) points: none refuses the file, harmonic or mean fills them")
      ->check(CLI::IsMember({"none", "harmonic", "mean"}));
  command.add_option("--level", level, "levelling after reading: none, mean or plane (least squares)")
      ->check(CLI::IsMember({"none", "mean", "plane"}));
}

TopographyReading TopographyOptions::read_with_report() const {
  TopographyReadOptions options;
  options.lx = size;
  options.ly = size_y;
  if (periodic) options.periodic = true;
  options.channel = channel;
  options.fill = parse_fill_method(fill).value_or(FillMethod::none);  // CLI11 has checked the value
  options.level = parse_levelling(level).value_or(Levelling::none);
  return read_topography_reading(file, options);
}

Surface TopographyOptions::read() const {
  return read_with_report().surface;
}

}  // namespace contactbench
