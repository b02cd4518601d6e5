// Pictures of a field file (app/load_fields.hpp, core/topography_io.hpp write_field): a map of the values on
// the grid with a colour bar in the field's unit, as PNG and SVG, drawn by gnuplot (as the load-area plots
// are; gnuplot-nox is in scripts/install-deps.sh). The contact set is drawn with one colour per class.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

#include "contactbench/core/topography_io.hpp"

namespace contactbench {

// A unit with an SI prefix chosen for numbers of `magnitude` in `unit` (Pa, m): values are multiplied by
// `factor` to be read in `label` ("MPa", "µm"). Units without a prefix (1) keep factor 1.
struct ScaledUnit {
  double factor = 1;
  std::string label;
};
ScaledUnit scaled_unit(double magnitude, const std::string& unit);

// The colour scale of a map: [low, high] in the scaled unit, what the colour bar shows. The field's minimum
// and maximum (a constant field: the value +- half its magnitude, or +-1 when 0).
struct ColourScale {
  double low = 0, high = 1;
  ScaledUnit unit;
};
ColourScale colour_scale(const Field& field);

// The gnuplot script drawing the field file `data` (read by gnuplot as a matrix: its '#' header is a
// comment) holding `field` into `png` and `svg`. `title` heads the picture.
void write_field_gnuplot_script(std::ostream& out, const Field& field, const std::string& data,
                                const std::string& title, const std::string& png, const std::string& svg);

// Draws `field`, whose values gnuplot reads from `data` (a file in the project's format holding them), under
// `title` into `png` and `svg` (either may be empty: not drawn), each written under a temporary name and
// renamed. Throws Error when gnuplot is missing or fails.
void draw_field(const Field& field, const std::filesystem::path& data, const std::string& title,
                const std::filesystem::path& png, const std::filesystem::path& svg);

// Draws `field_file` (a field or surface file in the project's format) into `png` and `svg` (either may be
// empty: not drawn), each written under a temporary name and renamed. Throws Error when gnuplot is missing
// or fails, naming the file.
void draw_field_picture(const std::filesystem::path& field_file, const std::filesystem::path& png,
                        const std::filesystem::path& svg);

}  // namespace contactbench
