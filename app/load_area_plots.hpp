// Load-area plots of a scene's run, like the paper's Figs. 6, 7 and 9: A/A0 against P/(E* A0) for every
// method on linear and on logarithmic axes (bounded by the data), the reference's error band, the relative
// error against the reference, and the legend in a panel of its own, as PNG and SVG, drawn by gnuplot.
#pragma once

#include <filesystem>
#include <ostream>

#include "contactbench/app/scene_run.hpp"

namespace contactbench {

// The gnuplot script that draws `curves.csv` of `report` into the files named by `png` and `svg`.
void write_gnuplot_script(std::ostream& out, const SceneReport& report, const std::string& png,
                          const std::string& svg);

// Writes folder/load_area.gp and runs gnuplot on it, making folder/load_area.png and .svg (each drawn under a
// temporary name and renamed). Returns false, with the reason on `warnings`, when gnuplot is not installed or
// fails: the numbers are in curves.csv either way.
bool draw_load_area_plots(const std::filesystem::path& folder, const SceneReport& report,
                          std::ostream& warnings);

}  // namespace contactbench
