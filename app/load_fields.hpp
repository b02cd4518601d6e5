// The field files of one solved load (a scene's `fields`, `contactbench bem --fields`): pressure [Pa], gap
// [m] and contact set (0 out of contact, 1 contact, 2 attractive zone out of contact), with the attraction
// [Pa] when the solve is adhesive; each as text (core/topography_io.hpp write_field) and, when asked, as PNG
// and SVG maps (app/field_picture.hpp).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

struct LoadFields {
  const HeightMap* pressure = nullptr;    // the repulsive pressure p [Pa]
  const HeightMap* gap = nullptr;         // [m]
  const HeightMap* attraction = nullptr;  // a [Pa] >= 0; null: not adhesive
};

// Writes <prefix>_load<k>_<quantity>.txt for each field of `fields` on `grid`, then the .png and .svg map of
// each beside it. Returns the files written. Maps that cannot be drawn (no gnuplot, or a grid above
// kMostPicturePoints) are told to `warning` once and skipped: the text files hold the numbers either way.
std::vector<std::string> write_load_fields(const std::string& prefix, std::size_t k, const Grid& grid,
                                           const LoadFields& fields,
                                           const std::function<void(const std::string&)>& warning);

// Grids above this many points get no maps while the solve runs (gnuplot reads the text field: minutes at
// 4096^2); `contactbench plot` draws one when asked.
inline constexpr Index kMostPicturePoints = 1024 * 1024;

// The quantities write_load_fields writes (adhesive: with "attraction").
std::vector<const char*> field_quantities(bool adhesive);

}  // namespace contactbench
