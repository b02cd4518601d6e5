// Reading and writing topography files (instrument exports, plain matrices, the project's own format).
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "contactbench/core/surface.hpp"

namespace contactbench {

// The file formats this project reads; detected from the first non-blank line.
enum class TopographyFormat {
  project,         // "# contactbench surface v1" header, written by write_surface, lossless
  interferometer,  // "h=NY w=NX", "pixel size=... UNIT", "data unit=...", "height conversion factor (->
                   // m)=..."
  gwyddion,  // Gwyddion text export: "# Channel:", "# Width: L UNIT", "# Height: L UNIT", "# Value units:"
  plain_matrix,  // whitespace-separated heights in metres, rows along y; sizes from the caller
};

std::string_view to_string(TopographyFormat format);

struct TopographyReadOptions {
  // Lateral sizes [m]. Required for a plain matrix (ly defaults to lx * ny / nx: square pixels).
  // For a file that carries its own sizes they must agree with it (1e-6 relative), else Error.
  std::optional<Real> lx;
  std::optional<Real> ly;
  // Periodicity. Default: false for instrument exports and plain matrices (measured data do not repeat),
  // the stored flag for the project's format.
  std::optional<bool> periodic;
};

// Detects the format and reads the file. Heights come back in metres, exactly as stored (no mean removed).
// Any defect throws InputError naming the file and the line: an empty file, a ragged row, a non-numeric
// token, NaN or Inf, a missing or non-positive size, an unknown unit, a header that disagrees with the data.
Surface read_topography(const std::filesystem::path& path, const TopographyReadOptions& options = {});

TopographyFormat detect_topography_format(const std::filesystem::path& path);

// Writes the project's format: a header with nx, ny, lx, ly, periodic, then heights in metres printed as the
// shortest decimal that reads back to the same double, so read_topography returns the surface bit for bit.
// Written to a temporary file and renamed.
void write_surface(const std::filesystem::path& path, const Surface& surface);

}  // namespace contactbench
