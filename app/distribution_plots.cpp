#include "contactbench/app/distribution_plots.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "contactbench/app/field_picture.hpp"
#include "contactbench/app/gnuplot_text.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ','))
    cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

bool has(const DistributionFile& f, const std::string& column) {
  for (const std::string& c : f.non_empty)
    if (c == column) return true;
  return false;
}

// One `plot` clause per column the file has numbers in: x, the column, its style and legend.
struct Curve {
  std::string column, style, title;
};

void write_plot(std::ostream& out, const DistributionFile& f, const std::string& csv, const std::string& x,
                const std::vector<Curve>& curves) {
  std::string separator = "plot ";
  for (const Curve& c : curves) {
    if (!has(f, c.column)) continue;
    out << separator << gnuplot_quote(csv) << " using " << x << ":\"" << c.column << "\" " << c.style
        << " title " << gnuplot_quote(c.title);
    separator = ", \\\n     ";
  }
  out << "\n";
}

void write_picture(std::ostream& out, const DistributionFile& f, const std::string& csv,
                   const std::string& title) {
  out << "set datafile separator comma\nset datafile columnheaders\n";
  out << "set title " << gnuplot_quote(title) << "\n";
  // The legend in a panel of its own, off the data (as the load-area plots).
  out << "set key outside right top vertical Left reverse\nset grid\nset tics out\n";
  switch (f.kind) {
    case DistributionKind::pressure:
      out << "unset logscale\nset xlabel 'pressure sigma / E*'\nset ylabel 'P(sigma) E*  (integral = "
             "A/A0)'\n";
      write_plot(out, f, csv, "\"sigma\"",
                 {{"bem_density", "with histeps lw 2 lc rgb '#1a1a1a'", "BEM histogram"},
                  {"persson_density", "with lines lw 2 lc rgb '#d95f02'", "Persson's diffusion solution"}});
      break;
    case DistributionKind::gap: {
      const ScaledUnit unit = scaled_unit(f.largest_x, "m");
      out << "set logscale y\nset format y '%.0e'\nset xlabel " << gnuplot_quote("gap g [" + unit.label + "]")
          << "\nset ylabel 'P(g) [1/m]  (integral = 1 - A/A0)'\n";
      write_plot(
          out, f, csv, "(column(\"gap\")*" + gnuplot_number(unit.factor) + ")",
          {{"density", "with histeps lw 2 lc rgb '#1a1a1a'", "BEM histogram"},
           {"plateau_density", "with histeps lw 1.5 lc rgb '#1b9e77'", "multi-plateaus (cut level)"},
           {"plateau_hertz_density", "with histeps lw 1.5 dt 2 lc rgb '#7570b3'",
            "Hertz-consistent plateaus (this project)"},
           {"summit_density", "with lines lw 2 lc rgb '#d95f02'", "GW-McCool, Gaussian undeformed gap"}});
      break;
    }
    case DistributionKind::patch_sizes:
      out << "set logscale xy\nset format y '%.0e'\nset xlabel 'patch size s [nodes]'\n"
             "set ylabel 'patches per size n(s)'\n";
      write_plot(
          out, f, csv, "\"size\"",
          {{"density_per_size", "with points pt 7 ps 1 lc rgb '#1a1a1a'", "BEM clusters"},
           {"bem_power_law", "with lines lw 2 lc rgb '#d95f02'", "power law fitted to the BEM"},
           {"plateau_density_per_size", "with points pt 6 ps 1.2 lc rgb '#1b9e77'", "multi-plateaus spots"}});
      break;
  }
}

std::string kind_name(DistributionKind kind) {
  switch (kind) {
    case DistributionKind::pressure:
      return "pressure distribution";
    case DistributionKind::gap:
      return "gap distribution";
    case DistributionKind::patch_sizes:
      break;
  }
  return "contact patch sizes";
}

}  // namespace

std::optional<DistributionFile> read_distribution_file(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  if (!in) return std::nullopt;
  DistributionFile f;
  std::string line;
  bool header = false;
  std::vector<bool> numbers;
  std::size_t high_edge = 1;
  while (std::getline(in, line)) {
    if (line.starts_with("#")) {
      const std::string mark = "at load P/(E* A0) = ";
      if (const auto at = line.find(mark); at != std::string::npos && f.load.empty()) {
        const auto begin = at + mark.size();
        f.load = line.substr(begin, line.find_first_of(": ", begin) - begin);
      }
      continue;
    }
    if (!header) {
      f.columns = split(line);
      if (f.columns.empty()) return std::nullopt;
      if (f.columns[0] == "sigma_low")
        f.kind = DistributionKind::pressure;
      else if (f.columns[0] == "gap_low")
        f.kind = DistributionKind::gap;
      else if (f.columns[0] == "size_low")
        f.kind = DistributionKind::patch_sizes;
      else
        return std::nullopt;
      numbers.assign(f.columns.size(), false);
      header = true;
      continue;
    }
    const std::vector<std::string> cells = split(line);
    for (std::size_t i = 0; i < cells.size() && i < numbers.size(); ++i)
      if (!cells[i].empty()) numbers[i] = true;
    if (cells.size() > high_edge)
      f.largest_x = std::max(f.largest_x, std::strtod(cells[high_edge].c_str(), nullptr));
  }
  if (!header) return std::nullopt;
  for (std::size_t i = 0; i < f.columns.size(); ++i)
    if (numbers[i]) f.non_empty.push_back(f.columns[i]);
  return f;
}

void write_distribution_gnuplot_script(std::ostream& out, const DistributionFile& file,
                                       const std::string& csv, const std::string& title,
                                       const std::string& png, const std::string& svg) {
  out << "# Made by contactbench (app/distribution_plots.cpp): the plot of " << csv << ".\n";
  if (!png.empty()) {
    out << "set terminal pngcairo noenhanced size 1000,600 font ',11'\nset output " << gnuplot_quote(png)
        << "\n";
    write_picture(out, file, csv, title);
  }
  if (!svg.empty()) {
    out << "set terminal svg noenhanced size 1000,600 dynamic font ',11'\nset output " << gnuplot_quote(svg)
        << "\n";
    write_picture(out, file, csv, title);
  }
  out << "unset output\n";
}

void draw_distribution_picture(const std::filesystem::path& csv, const std::filesystem::path& png,
                               const std::filesystem::path& svg) {
  const std::optional<DistributionFile> file = read_distribution_file(csv);
  if (!file)
    throw Error(csv.string() +
                ": not a distribution CSV of contactbench (its column line starts with none of sigma_low, "
                "gap_low, size_low)");
  const std::string title = csv.filename().string() + ": " + kind_name(file->kind) +
                            " at P/(E* A0) = " + (file->load.empty() ? std::string("?") : file->load);
  const std::string csv_path = std::filesystem::absolute(csv).string();
  run_gnuplot(png, svg, csv,
              [&](std::ostream& out, const std::string& png_path, const std::string& svg_path) {
                write_distribution_gnuplot_script(out, *file, csv_path, title, png_path, svg_path);
              });
}

bool draw_distribution_plots(const std::filesystem::path& folder, const SceneReport& report,
                             std::ostream& warnings) {
  bool all = true;
  for (const MethodResult& m : report.methods) {
    if (!m.curve.distributions) continue;
    for (const std::string suffix : {"_pressure_distribution", "_gap_distribution", "_patch_sizes"}) {
      const std::filesystem::path csv = folder / (m.label + suffix + ".csv");
      try {
        draw_distribution_picture(csv, folder / (m.label + suffix + ".png"),
                                  folder / (m.label + suffix + ".svg"));
      } catch (const Error& e) {
        warnings << "contactbench run: warning: " << e.what() << " (the numbers are in the CSV)\n";
        all = false;
      }
    }
  }
  return all;
}

}  // namespace contactbench
