#include "contactbench/app/topography_options.hpp"

#include <string>
#include <string_view>
#include <vector>

#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

// CLI11 checks membership in strings; core declares the accepted names once, as views.
std::vector<std::string> as_strings(const std::vector<std::string_view>& names) {
  return {names.begin(), names.end()};
}

}  // namespace

std::string readable_formats_help() {
  // docs/formats.md has the table; detection is by content, so the extensions are what instruments write.
  return ".x3p (ISO 25178-72), .sdf (ISO 25178-71), .npy (NumPy), .dat (Zygo MetroPro), .di/.spm "
         "(Bruker Nanoscope), .plu (Sensofar), .sur (Digital Surf), .opd (Wyko), .nc (NetCDF classic), .gwy "
         "(Gwyddion), and "
         "text: the project's format, an interferometer export, a Gwyddion text export, a plain matrix "
         "(blank-, comma- or semicolon-separated), an x y z point list on a regular grid, a line scan (x h "
         "text, Dektak CSV: stats and the analytic theories of a scene)";
}

void TopographyOptions::add_to(CLI::App& command, const std::string& periodic_effect) {
  command
      .add_option("FILE", file,
                  "topography file, detected by content: " + readable_formats_help() +
                      ". Matrices and .npy carry no size (give --size) and no unit (give --unit unless "
                      "they are metres)")
      ->required();
  command.add_option("--size", size, "lateral size along x [m] (for files that carry none)");
  command.add_option("--size-y", size_y, "lateral size along y [m] (default: square pixels)");
  command.add_flag("--periodic", periodic, "treat the surface as periodic (" + periodic_effect + ")");
  command.add_option("--channel", channel,
                     "channel of a multi-channel file, by name or 0-based index (default: the first height "
                     "channel)");
  command
      .add_option("--fill", fill,
                  "invalid (unmeasured) points: none refuses the file, harmonic or mean fills them")
      ->check(CLI::IsMember(as_strings(fill_method_names())));
  command
      .add_option("--crop", crop,
                  "the region read, before invalid points are counted or filled: measured (the largest fully "
                  "measured rectangle), px:X0,Y0,NX,NY (pixels) or m:X0,Y0,LX,LY (metres)")
      ->check([](const std::string& text) {
        return parse_crop(text) ? std::string() : std::string("expected ") + kCropAccepted;
      });
  command
      .add_option("--align-rows", align_rows,
                  "per scan line (row), after filling: none, mean, median or linear (each row's own line)")
      ->check(CLI::IsMember(as_strings(row_alignment_names())));
  command
      .add_option(
          "--level", level,
          "levelling after row alignment: none, mean, plane (degree 1) or quadratic (degree 2), least "
          "squares")
      ->check(CLI::IsMember(as_strings(levelling_names())));
  command
      .add_option("--unit", unit,
                  "unit of the numbers of a file that states none (matrices, .npy, x y z lists): m, mm, um, "
                  "nm or pm; without it they are metres, and Sq above 1 mm or below 1 pm is refused")
      ->check(CLI::IsMember({"m", "mm", "um", "nm", "pm"}));
}

TopographyReading TopographyOptions::read_with_report() const {
  TopographyReadOptions options;
  options.lx = size;
  options.ly = size_y;
  if (periodic) options.periodic = true;
  options.channel = channel;
  options.fill = parse_fill_method(fill).value_or(FillMethod::none);  // CLI11 has checked the value
  options.level = parse_levelling(level).value_or(Levelling::none);
  options.unit = unit;
  if (crop) options.crop = parse_crop(*crop);  // CLI11 has checked the value
  options.align_rows = parse_row_alignment(align_rows).value_or(RowAlignment::none);
  return read_topography_reading(file, options);
}

Surface TopographyOptions::read() const {
  return read_with_report().surface;
}

}  // namespace contactbench
