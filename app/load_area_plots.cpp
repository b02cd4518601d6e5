#include "contactbench/app/load_area_plots.hpp"

#include <cstdlib>
#include <string>

#include "contactbench/core/atomic_file.hpp"

namespace contactbench {

namespace {

// A path inside single quotes for the shell: a quote in it becomes '\''.
std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char ch : text)
    quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

// Text inside gnuplot's single quotes, where a quote is written twice (a method's note is free text).
std::string gnuplot_quote(const std::string& text) {
  std::string quoted = "'";
  for (const char ch : text)
    quoted += ch == '\'' ? std::string("''") : std::string(1, ch);
  return quoted + "'";
}

// The gnuplot commands of the two panels: linear axes (as the paper draws them) and log-log (small loads).
void write_panels(std::ostream& out, const SceneReport& report) {
  out << "set multiplot layout 1,2 title " << '"' << report.scene.name
      << ": real contact area against load\"\n";
  for (int panel = 0; panel < 2; ++panel) {
    if (panel == 0) {
      out << "unset logscale\nset key top left\n";
    } else {
      out << "set logscale xy\nset key bottom right\n";
    }
    out << "set xlabel 'P/(E* A0)'\nset ylabel 'A/A0'\nset grid\n";
    out << "plot ";
    for (std::size_t m = 0; m < report.methods.size(); ++m) {
      const std::string& label = report.methods[m].label;
      const bool reference = label == report.scene.reference;
      // Along a load path, the method's steps in order (<label>_path.csv: load, then area in column 4), so
      // that loading and unloading draw their loops; otherwise its rows of curves.csv.
      const bool path = !report.methods[m].curve.path_columns.empty();
      out << (m == 0 ? "" : ", \\\n     ");
      if (path)
        out << gnuplot_quote(label + "_path.csv") << " using 2:4";
      else
        out << "'curves.csv' using (strcol(1) eq '" << label << "' ? $3 : NaN):4";
      out << " with linespoints " << (reference ? "lw 3 pt 7 ps 0.8 lc rgb 'black'" : "lw 1.5") << " title "
          << gnuplot_quote(label + (reference ? " (reference)" : "") + (path ? " (load path)" : "") +
                           report.methods[m].note_suffix());
    }
    out << '\n';
  }
  out << "unset multiplot\n";
}

}  // namespace

void write_gnuplot_script(std::ostream& out, const SceneReport& report, const std::string& png,
                          const std::string& svg) {
  out << "# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder "
         "redraws\n"
         "# the plots from curves.csv.\n"
         "set datafile separator ','\nset datafile missing ''\n";
  out << "set terminal pngcairo noenhanced size 1400,600 font ',11'\nset output '" << png << "'\n";
  write_panels(out, report);
  out << "set terminal svg noenhanced size 1400,600 dynamic font ',11'\nset output '" << svg << "'\n";
  write_panels(out, report);
  out << "unset output\n";
}

bool draw_load_area_plots(const std::filesystem::path& folder, const SceneReport& report,
                          std::ostream& warnings) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) {
    warnings << "contactbench run: warning: gnuplot is not installed (Debian: gnuplot-nox), so no plots were "
                "drawn; the curves are in "
             << (folder / "curves.csv").string() << '\n';
    return false;
  }
  const std::string png_partial = ".load_area.png.partial", svg_partial = ".load_area.svg.partial";
  write_file_atomically(folder / "load_area.gp", [&](std::ostream& out) {
    write_gnuplot_script(out, report, png_partial, svg_partial);
  });
  const std::string command = "cd " + shell_quote(folder.string()) + " && gnuplot load_area.gp";
  if (std::system(command.c_str()) != 0) {
    warnings << "contactbench run: warning: gnuplot failed on " << (folder / "load_area.gp").string()
             << "; no plots were drawn\n";
    std::filesystem::remove(folder / png_partial);
    std::filesystem::remove(folder / svg_partial);
    return false;
  }
  std::filesystem::rename(folder / png_partial, folder / "load_area.png");
  std::filesystem::rename(folder / svg_partial, folder / "load_area.svg");
  return true;
}

}  // namespace contactbench
