#include "contactbench/app/line_scan_surface.hpp"

#include <sstream>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/line_scan.hpp"
#include "contactbench/core/profile_levelling.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

bool is_line_scan(const SurfaceSpec& spec) {
  const auto* file = std::get_if<FileSurfaceSpec>(&spec.source);
  return file && detect_topography_format(file->path) == TopographyFormat::line_scan;
}

LineScanSurface read_line_scan_surface(const SurfaceSpec& spec) {
  const auto& file = std::get<FileSurfaceSpec>(spec.source);
  const auto refuse = [&](const std::string& key) {
    throw InputError(file.path, 0,
                     "is a line scan (one profile along x); surface." + key +
                         " is for a 2-D file and does not apply: a line scan takes unit and level only");
  };
  if (file.size_x || file.size_y) refuse("size");
  if (file.periodic) refuse("periodic");
  if (file.channel) refuse("channel");
  if (file.fill != FillMethod::none) refuse("fill");
  if (file.crop) refuse("crop");
  if (file.align_rows != RowAlignment::none) refuse("align_rows");

  TopographyReadOptions options;
  options.unit = file.unit;
  const formats::LineScan scan = formats::read_line_scan(file.path, options);
  try {
    const std::vector<Real> heights = level_profile(scan.x, scan.heights, file.level);
    const ProfileStatistics statistics = profile_statistics(scan.x, heights);
    const auto n = static_cast<Index>(heights.size());
    const Grid grid{.nx = n, .ny = 1, .lx = statistics.length, .ly = statistics.length, .periodic = false};
    HeightMap row(1, n);
    for (Index k = 0; k < n; ++k)
      row(0, k) = heights[static_cast<std::size_t>(k)] - statistics.mean;
    return LineScanSurface{.profile = Surface(grid, std::move(row)),
                           .statistics = statistics,
                           .moments = isotropic_moments(statistics),
                           .source = scan.source,
                           .level = file.level};
  } catch (const InputError&) {
    throw;
  } catch (const Error& error) {
    throw InputError(file.path, 0, error.what());
  }
}

std::string describe(const LineScanSurface& scan) {
  const ProfileStatistics& p = scan.statistics;
  std::ostringstream text;
  text.precision(4);
  text << "Line scan (" << scan.source << ") of " << p.points << " points over " << p.length * 1e6 << " um, "
       << (p.uniform ? "uniformly sampled" : "unevenly sampled (no m4)") << ", levelled "
       << to_string(scan.level) << ": Rq = " << p.rq << " m, rms slope = " << p.rms_slope
       << ". Isotropy assumed: the theories see the isotropic surface whose every profile has these moments "
          "(m2x = m2y = the profile's m2; areal gbar = sqrt(2 m2)); nominal area "
       << p.length * 1e6 << " x " << p.length * 1e6 << " um";
  return text.str();
}

}  // namespace contactbench
