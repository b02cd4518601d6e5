#include "contactbench/app/adhesive_path_plot.hpp"

#include <fstream>

#include "contactbench/app/adhesive_path_csv.hpp"
#include "contactbench/app/gnuplot_text.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// One panel: `y` against `x` (gnuplot expressions of the columns), the approach leg and the retract leg as
// two curves with points, each row kept only on its own leg.
void write_legs(std::ostream& out, const std::string& csv, const std::string& x, const std::string& y) {
  const auto leg = [&](const char* name, const char* style, const char* title) {
    out << gnuplot_quote(csv) << " using " << x << ":(strcol(1) eq '" << name << "' ? " << y << " : NaN) "
        << style << " title '" << title << "'";
  };
  out << "plot ";
  leg("approach", "with linespoints lw 2 pt 7 ps 0.5 lc rgb '#1b9e77'", "approach");
  out << ", \\\n     ";
  leg("retract", "with linespoints lw 2 pt 5 ps 0.5 lc rgb '#d95f02'", "retract");
  out << "\n";
}

void write_picture(std::ostream& out, const std::string& csv, const std::string& title) {
  out << "set datafile separator comma\nset datafile columnheaders\nset grid\nset tics out\n";
  out << "set multiplot layout 1,2 title " << gnuplot_quote(title) << "\n";
  // Each legend where its panel has no data: the loads rise toward large separations, the areas fall.
  out << "set key bottom right\nset xlabel 'separation d [um]'\n"
         "set ylabel 'net load P/(E* A0)  (< 0: tensile)'\n";
  write_legs(out, csv, "(column(\"separation\")*1e6)", "column(\"load\")");
  out << "set key top right\nset xlabel 'net load P/(E* A0)'\nset ylabel 'repulsive contact area A/A0'\n";
  write_legs(out, csv, "(column(\"load\"))", "column(\"contact_fraction\")");
  out << "unset multiplot\n";
}

}  // namespace

bool is_adhesive_path_file(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  while (std::getline(in, line))
    if (!line.starts_with("#")) return line == kAdhesivePathColumns;
  return false;
}

void write_adhesive_path_gnuplot_script(std::ostream& out, const std::string& csv, const std::string& title,
                                        const std::string& png, const std::string& svg) {
  out << "# Made by contactbench (app/adhesive_path_plot.cpp): the plot of " << csv << ".\n";
  if (!png.empty()) {
    out << "set terminal pngcairo noenhanced size 1200,520 font ',11'\nset output " << gnuplot_quote(png)
        << "\n";
    write_picture(out, csv, title);
  }
  if (!svg.empty()) {
    out << "set terminal svg noenhanced size 1200,520 dynamic font ',11'\nset output " << gnuplot_quote(svg)
        << "\n";
    write_picture(out, csv, title);
  }
  out << "unset output\n";
}

void draw_adhesive_path_picture(const std::filesystem::path& csv, const std::filesystem::path& png,
                                const std::filesystem::path& svg) {
  if (!is_adhesive_path_file(csv))
    throw Error(csv.string() + ": not an approach-retract path CSV of contactbench (its column line is not " +
                std::string(kAdhesivePathColumns) + ")");
  const std::string csv_path = std::filesystem::absolute(csv).string();
  const std::string title = csv.filename().string() + ": approach and retract";
  run_gnuplot(png, svg, csv,
              [&](std::ostream& out, const std::string& png_path, const std::string& svg_path) {
                write_adhesive_path_gnuplot_script(out, csv_path, title, png_path, svg_path);
              });
}

}  // namespace contactbench
