// The picture of an approach-retract path (app/adhesive_path_csv.hpp; docs/theory.md 10.7): the net load
// against the separation, the approach leg and the retract leg in two colours, so that the hysteresis loop,
// the jumps into and out of contact and the pull-off show; beside it the contact area against the load on
// both legs. Drawn by gnuplot as PNG and SVG.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>

namespace contactbench {

// Whether `csv` is an approach-retract path CSV (its column line is kAdhesivePathColumns).
bool is_adhesive_path_file(const std::filesystem::path& csv);

// The gnuplot script drawing `csv` into `png` and `svg` (either may be empty) under `title`.
void write_adhesive_path_gnuplot_script(std::ostream& out, const std::string& csv, const std::string& title,
                                        const std::string& png, const std::string& svg);

// Draws `csv` into `png` and `svg` (either may be empty), each whole or absent. Throws Error when the file
// is not a path CSV, or gnuplot is missing or fails.
void draw_adhesive_path_picture(const std::filesystem::path& csv, const std::filesystem::path& png,
                                const std::filesystem::path& svg);

}  // namespace contactbench
