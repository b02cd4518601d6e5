// One-dimensional line scans (docs/formats.md "line scans"): a stylus profilometer's profile, h(x) at n
// points along one line, as x h text (blank- or comma-separated, optionally under a header naming the
// columns) or a Bruker Dektak CSV export. A line scan is not a surface: read_topography refuses it, and
// `contactbench stats` gives its profile statistics (core/profile_statistics.hpp).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "contactbench/core/formats/text_lines.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::formats {

struct LineScan {
  std::vector<Real> x;        // positions along the line [m], strictly increasing
  std::vector<Real> heights;  // [m]
  std::string source;         // "dektak" or "x h text", for reports
  std::string unit;           // the unit the heights were written in
};

// Whether these lines are a line scan: a Dektak export (a "Scan Data" line, then "Lateral ..."), or lines of
// two finite numbers with x strictly increasing, at least three under one line naming the two columns, at
// least eight without one (fewer are more likely a two-column matrix).
bool looks_like_line_scan(std::span<const Line> lines);

// Reads a line scan. Units: Dektak names them in its column header; a header such as "X_(microns),y1" names
// that of x; whatever the file does not name is options.unit, else metres with the plausibility rule of the
// other unit-less files (docs/formats.md "units"). Any defect throws InputError naming the file and line.
LineScan read_line_scan(const std::filesystem::path& path, const TopographyReadOptions& options = {});

}  // namespace contactbench::formats
