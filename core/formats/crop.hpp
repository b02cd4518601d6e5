// A region of a topography (docs/formats.md "regions and levelling"): a rectangle given in pixels or in
// metres, or the largest rectangle of the grid whose every point was measured. Cropping runs first, before
// invalid points are counted or filled, so that a file measured over part of its grid (sur-3.sur) can be read
// without inventing heights.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

struct CropSpec {
  enum class Kind { pixels, metres, measured };
  Kind kind = Kind::pixels;
  // pixels: first column, first row, columns, rows; metres: x0, y0, width, height from the grid's corner
  // (point ix at x = ix * dx). Unused for measured.
  Real x0 = 0, y0 = 0, width = 0, height = 0;
};

// "measured", "px:X0,Y0,NX,NY" or "m:X0,Y0,LX,LY"; nullopt for anything else.
std::optional<CropSpec> parse_crop(const std::string& text);
std::string to_string(const CropSpec& crop);
inline constexpr const char* kCropAccepted =
    "measured (the largest fully measured rectangle), px:X0,Y0,NX,NY (pixels) or m:X0,Y0,LX,LY (metres)";

namespace formats {

// A grid of values (NaN: invalid) with its sizes, cropped in place. The metres rectangle takes the points
// whose positions lie inside it; sizes stay count x step. InputError naming the file when the rectangle is
// empty or leaves the grid, or when no point is measured.
struct CropResult {
  Index x0 = 0, y0 = 0;  // the first column and row kept
};
CropResult crop_values(const std::filesystem::path& path, std::vector<Real>& values, Index& nx, Index& ny,
                       Real& lx, Real& ly, const CropSpec& crop);

}  // namespace formats
}  // namespace contactbench
