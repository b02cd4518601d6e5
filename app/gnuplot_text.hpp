// Text that the gnuplot scripts of the load-area plots and the field maps write (app/load_area_plots.cpp,
// app/field_picture.cpp): paths quoted for the shell, strings for gnuplot, numbers that read back exactly.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

namespace contactbench {

// A path inside single quotes for the shell: a quote in it becomes '\''.
std::string shell_quote(const std::string& text);

// Text inside gnuplot's single quotes, where a quote is written twice (titles and notes are free text).
std::string gnuplot_quote(const std::string& text);

// A number for a data block or a range: the shortest decimal that reads back to the same double; NaN as
// gnuplot reads it.
std::string gnuplot_number(double value);

// Whether a gnuplot is on the PATH.
bool gnuplot_available();

// Draws with gnuplot into `png` and `svg` (either may be empty): `write_script(out, png_path, svg_path)`
// writes the script for the absolute temporary paths it is given, and each picture is renamed into place
// only when gnuplot succeeds, so that a picture is whole or absent. `drawn` names the file drawn in errors.
// Throws Error when gnuplot is missing or fails.
using GnuplotScript = std::function<void(std::ostream&, const std::string& png, const std::string& svg)>;
void run_gnuplot(const std::filesystem::path& png, const std::filesystem::path& svg,
                 const std::filesystem::path& drawn, const GnuplotScript& write_script);

}  // namespace contactbench
