#include "contactbench/app/field_picture.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "contactbench/app/gnuplot_text.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

bool is_contact_set(const Field& field) {
  return field.quantity == "contact";
}

// The symbol of a quantity on the colour bar.
std::string symbol(const std::string& quantity) {
  if (quantity == "pressure") return "pressure p";
  if (quantity == "gap") return "gap g";
  if (quantity == "attraction") return "attraction a";
  if (quantity == "traction") return "traction t = p - a";
  if (quantity == "height") return "height h";
  return quantity;
}

// The commands of one picture (the terminal and output set before).
void write_map(std::ostream& out, const Field& field, const std::string& data, const std::string& title) {
  const Grid& grid = field.values.grid();
  const ScaledUnit lateral = scaled_unit(std::max(grid.lx, grid.ly), "m");
  const double dx = grid.lx / static_cast<double>(grid.nx) * lateral.factor;
  const double dy = grid.ly / static_cast<double>(grid.ny) * lateral.factor;
  out << "set title " << gnuplot_quote(title) << "\n";
  out << "set size ratio -1\nunset key\nset tics out\n";
  out << "set xrange [0:" << gnuplot_number(grid.nx * dx)
      << "]\nset yrange [0:" << gnuplot_number(grid.ny * dy) << "]\n";
  out << "set xlabel " << gnuplot_quote("x [" + lateral.label + "]") << "\nset ylabel "
      << gnuplot_quote("y [" + lateral.label + "]") << "\n";
  // Pixel (column i, row j) covers [i dx, (i+1) dx] x [j dy, (j+1) dy]: gnuplot's matrix gives i as $1, j
  // as $2 and draws an image pixel centred on the point given.
  const std::string where = "(($1+0.5)*" + gnuplot_number(dx) + "):(($2+0.5)*" + gnuplot_number(dy) + ")";
  if (is_contact_set(field)) {
    // One flat colour per class (maxcolors): the attractive zone only when the file has one.
    const bool attraction = field.values.heights().maxCoeff() > 1;
    out << "set palette maxcolors " << (attraction ? 3 : 2) << "\n";
    out << "set palette defined (0 '#d9d9d9', 1 '#1a1a1a'" << (attraction ? ", 2 '#e08a1e'" : "") << ")\n";
    out << "set cbrange [-0.5:" << (attraction ? "2.5" : "1.5") << "]\nset rmargin 16\n";
    out << "set cbtics ('no contact' 0, 'contact' 1" << (attraction ? ", 'attracted' 2" : "") << ")\n";
    out << "set cblabel 'contact set'\n";
    out << "plot " << gnuplot_quote(data) << " matrix using " << where << ":3 with image\n";
    return;
  }
  const ColourScale scale = colour_scale(field);
  // Viridis (perceptually uniform, readable in grey): eight of its stops.
  out << "set palette defined (0 '#440154', 1 '#46327e', 2 '#365c8d', 3 '#277f8e', 4 '#1fa187', 5 '#4ac16d', "
         "6 '#a0da39', 7 '#fde725')\n";
  out << "set cbrange [" << gnuplot_number(scale.low) << ":" << gnuplot_number(scale.high)
      << "]\nset cbtics auto\n";
  out << "set cblabel " << gnuplot_quote(symbol(field.quantity) + " [" + scale.unit.label + "]") << "\n";
  out << "plot " << gnuplot_quote(data) << " matrix using " << where << ":($3*"
      << gnuplot_number(scale.unit.factor) << ") with image\n";
}

}  // namespace

ScaledUnit scaled_unit(double magnitude, const std::string& unit) {
  if (unit != "m" && unit != "Pa") return {1, unit};
  struct Prefix {
    double factor;
    const char* name;
  };
  // Largest first: the first prefix with magnitude * factor <= 1000 ... read as 1 to 999.
  static constexpr Prefix prefixes[] = {{1e-9, "G"}, {1e-6, "M"}, {1e-3, "k"}, {1, ""},    {1e3, "m"},
                                        {1e6, "µ"},  {1e9, "n"},  {1e12, "p"}, {1e15, "f"}};
  const bool metres = unit == "m";
  for (const Prefix& p : prefixes) {
    if (metres && (p.factor < 1 || p.factor > 1e12)) continue;  // no km; pm at least
    if (!metres && p.factor > 1) continue;                      // no mPa
    if (magnitude * p.factor >= 1 || p.factor == (metres ? 1e12 : 1))
      return {p.factor, std::string(p.name) + unit};
  }
  return {1, unit};
}

ColourScale colour_scale(const Field& field) {
  const HeightMap& values = field.values.heights();
  double low = values.minCoeff(), high = values.maxCoeff();
  ColourScale scale;
  scale.unit = scaled_unit(std::max(std::abs(low), std::abs(high)), field.unit);
  low *= scale.unit.factor;
  high *= scale.unit.factor;
  if (!(high > low)) {  // a constant field: a scale around its value
    const double half = low == 0 ? 1 : std::abs(low) / 2;
    low -= half;
    high += half;
  }
  scale.low = low;
  scale.high = high;
  return scale;
}

void write_field_gnuplot_script(std::ostream& out, const Field& field, const std::string& data,
                                const std::string& title, const std::string& png, const std::string& svg) {
  out << "# Made by contactbench (app/field_picture.cpp): the map of " << data << ".\n";
  const Grid& grid = field.values.grid();
  // About 700 pixels for the map's longer side, its aspect kept, room for the colour bar.
  const double aspect = grid.ly / grid.lx;
  const int width = 900, height = static_cast<int>(std::clamp(700 * aspect + 120, 300.0, 1400.0));
  if (!png.empty()) {
    out << "set terminal pngcairo noenhanced size " << width << "," << height << " font ',11'\nset output "
        << gnuplot_quote(png) << "\n";
    write_map(out, field, data, title);
  }
  if (!svg.empty()) {
    out << "set terminal svg noenhanced size " << width << "," << height << " dynamic font ',11'\nset output "
        << gnuplot_quote(svg) << "\n";
    write_map(out, field, data, title);
  }
  out << "unset output\n";
}

void draw_field(const Field& field, const std::filesystem::path& data, const std::string& title,
                const std::filesystem::path& png, const std::filesystem::path& svg) {
  const std::string data_path = std::filesystem::absolute(data).string();
  run_gnuplot(png, svg, data,
              [&](std::ostream& out, const std::string& png_path, const std::string& svg_path) {
                write_field_gnuplot_script(out, field, data_path, title, png_path, svg_path);
              });
}

void draw_field_picture(const std::filesystem::path& field_file, const std::filesystem::path& png,
                        const std::filesystem::path& svg) {
  draw_field(read_field(field_file), field_file, field_file.filename().string(), png, svg);
}

}  // namespace contactbench
