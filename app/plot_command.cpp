// contactbench plot FILE: the map of a field file the project writes (pressure, gap, contact set, attraction)
// or of any surface file it reads (as a height map), as PNG and SVG with a colour bar in units
// (app/field_picture.hpp); or a distribution CSV of a scene's run (app/distribution_plots.hpp).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include <unistd.h>

#include "contactbench/app/adhesive_path_plot.hpp"
#include "contactbench/app/cli.hpp"
#include "contactbench/app/distribution_plots.hpp"
#include "contactbench/app/field_picture.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_readers.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

struct PlotOptions {
  TopographyOptions topography;  // FILE and, for a surface file, what the file may not say
  std::string out;               // FILE.png or FILE.svg; empty: both, beside FILE with its extension replaced
};

// Whether `path` starts as the project's text files do (fields and surfaces): then gnuplot reads it as is.
bool is_project_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  return first.starts_with(formats::project_prefix);
}

void run_plot(const PlotOptions& o) {
  const std::filesystem::path input(o.topography.file);
  std::filesystem::path png, svg;
  if (o.out.empty()) {
    png = std::filesystem::path(input).replace_extension(".png");
    svg = std::filesystem::path(input).replace_extension(".svg");
  } else {
    const std::string extension = std::filesystem::path(o.out).extension().string();
    if (extension != ".png" && extension != ".svg")
      throw Error("--out " + o.out + ": the picture's type is its extension: .png or .svg");
    (extension == ".png" ? png : svg) = o.out;
  }
  for (const auto& path : {png, svg})
    if (!path.empty()) check_output_file(path, input, "--out");
  if (input.extension() == ".csv" && is_adhesive_path_file(input)) {
    // An approach-retract path (app/adhesive_path_plot.hpp).
    draw_adhesive_path_picture(input, png, svg);
  } else if (input.extension() == ".csv") {
    // A distribution a scene's run wrote (app/distribution_plots.hpp); any other CSV is refused by name.
    draw_distribution_picture(input, png, svg);
  } else if (is_project_file(input)) {
    draw_field_picture(input, png, svg);
  } else {
    // Any other surface format: its heights [m] written in the project's format for gnuplot to read.
    const Surface surface = o.topography.read();
    const std::filesystem::path data =
        (png.empty() ? svg : png).parent_path() /
        ("." + input.filename().string() + ".heights.partial." + std::to_string(::getpid()) + ".txt");
    write_field(data, Field{surface, "height", "m"});
    try {
      draw_field(Field{surface, "height", "m"}, data, input.filename().string(), png, svg);
    } catch (...) {
      std::filesystem::remove(data);
      throw;
    }
    std::filesystem::remove(data);
  }
  std::cout << "Drawn: " << (png.empty() ? "" : png.string()) << (png.empty() || svg.empty() ? "" : ", ")
            << (svg.empty() ? "" : svg.string()) << "\n";
}

}  // namespace

void add_plot_command(CLI::App& parent) {
  auto options = std::make_shared<PlotOptions>();
  CLI::App* command = parent.add_subcommand(
      "plot",
      "Draw a field file (pressure, gap, contact set or attraction of a solved load, written by `bem "
      "--fields` "
      "and a scene's `fields`) or any surface file (as a height map): a map with a colour bar in the field's "
      "unit, as PNG and SVG (gnuplot). A distribution CSV of a run (<label>_pressure_distribution.csv, "
      "_gap_distribution.csv, _patch_sizes.csv) is drawn as its histogram beside the theories' columns; an "
      "approach-retract path CSV (`bem --approach-retract`, a scene's <label>_approach_retract.csv) as load "
      "against separation and area against load, approach and retract legs apart.");
  options->topography.add_to(*command, "nothing for the picture");
  command
      ->add_option("--out", options->out,
                   "the picture, FILE.png or FILE.svg (default: both, beside FILE, its extension replaced)")
      ->check(refuse_empty_output_name);
  command->callback([options] { run_plot(*options); });
}

}  // namespace contactbench
