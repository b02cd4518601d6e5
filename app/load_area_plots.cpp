#include "contactbench/app/load_area_plots.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

#include "contactbench/app/gnuplot_text.hpp"
#include "contactbench/core/atomic_file.hpp"

namespace contactbench {

namespace {

// A legend entry of one or two lines, in gnuplot's double quotes (where \\n is a line break and a backslash
// or a double quote is escaped): the second line, indented, when `second` is not empty.
std::string gnuplot_lines(const std::string& first, const std::string& second) {
  std::string quoted = "\"";
  const auto append = [&](const std::string& text) {
    for (const char ch : text) {
      if (ch == '\\' || ch == '"') quoted += '\\';
      quoted += ch;
    }
  };
  append(first);
  if (!second.empty()) {
    quoted += "\\n    ";
    append(second);
  }
  return quoted + "\"";
}

// The axis label, typeset by gnuplot's enhanced text (italic symbols, E*, A with subscript 0). gnuplot's
// text has no stacked fraction: the ratio is written with a slash.
constexpr const char* kLoadLabel = "{/:Italic P} / ({/:Italic E}^*{/:Italic A}_0)";
constexpr const char* kAreaLabel = "{/:Italic A} / {/:Italic A}_0";

struct PlotData {
  std::size_t reference = std::numeric_limits<std::size_t>::max();  // index in report.methods; max: none
  // Bounds of the finite positive values, for the log axes (the data's decades, not gnuplot's rounding).
  double load_min = std::numeric_limits<double>::infinity(), load_max = 0;
  double area_min = std::numeric_limits<double>::infinity(), area_max = 0;
  std::vector<std::string> stops;  // per method: "" or the note where its curve stops
};

PlotData plot_data(const SceneReport& report) {
  PlotData data;
  data.stops.resize(report.methods.size());
  const std::vector<Real>& loads = report.loads();
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& method = report.methods[m];
    if (method.label == report.scene.reference) data.reference = m;
    const std::vector<Real>& area = method.curve.area_fraction;
    std::size_t last_finite = area.size();
    for (std::size_t k = 0; k < area.size(); ++k) {
      if (!std::isfinite(area[k])) continue;
      last_finite = k;
      if (area[k] > 0 && loads[k] > 0) {
        data.load_min = std::min(data.load_min, loads[k]);
        data.load_max = std::max(data.load_max, loads[k]);
        data.area_min = std::min(data.area_min, area[k]);
        data.area_max = std::max(data.area_max, area[k]);
      }
    }
    // A method that answers up to some load and no further (a theory outside its range): said in the legend.
    if (last_finite < area.size() && last_finite + 1 < area.size()) {
      std::ostringstream note;
      note.precision(3);
      note << "no value above P/(E* A0) = " << loads[last_finite];
      data.stops[m] = note.str();
    } else if (last_finite == area.size() && !area.empty()) {
      data.stops[m] = "no value at any load";
    }
  }
  return data;
}

// A column of a method's load path by name; null when the method has no path.
const std::vector<Real>* path_column(const MethodCurve& curve, const std::string& name) {
  for (const auto& [key, values] : curve.path_columns)
    if (key == name) return &values;
  return nullptr;
}

// One data block per method: load, A/A0, the band [A - error, A + error] (NaN without an error estimate),
// the relative error A/A_ref - 1 (NaN without a reference value) and the reference's relative band.
void write_data_blocks(std::ostream& out, const SceneReport& report, const PlotData& data) {
  const std::vector<Real>& loads = report.loads();
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodCurve& curve = report.methods[m].curve;
    out << "$method" << m << " << EOD\n";
    for (std::size_t k = 0; k < loads.size(); ++k) {
      const double area = k < curve.area_fraction.size() ? curve.area_fraction[k] : NAN;
      const double error = k < curve.area_fraction_error.size() ? curve.area_fraction_error[k] : NAN;
      double reference = NAN, reference_error = NAN;
      if (data.reference < report.methods.size()) {
        const MethodCurve& r = report.methods[data.reference].curve;
        reference = k < r.area_fraction.size() ? r.area_fraction[k] : NAN;
        reference_error = k < r.area_fraction_error.size() ? r.area_fraction_error[k] : NAN;
      }
      const bool has_reference = std::isfinite(reference) && reference > 0;
      out << gnuplot_number(loads[k]) << ' ' << gnuplot_number(area) << ' ' << gnuplot_number(area - error)
          << ' ' << gnuplot_number(area + error) << ' '
          << gnuplot_number(has_reference ? area / reference - 1 : NAN) << ' '
          << gnuplot_number(has_reference ? reference_error / reference : NAN) << '\n';
    }
    out << "EOD\n";
    // Along a load path (loads.path = "as listed"), the method's steps in order: the loops of loading and
    // unloading, drawn over its curve (the curve holds each load's first step only).
    const std::vector<Real>* path_load = path_column(curve, "load");
    const std::vector<Real>* path_area = path_column(curve, "area_fraction");
    if (path_load && path_area) {
      out << "$path" << m << " << EOD\n";
      for (std::size_t k = 0; k < path_load->size() && k < path_area->size(); ++k)
        out << gnuplot_number((*path_load)[k]) << ' ' << gnuplot_number((*path_area)[k]) << '\n';
      out << "EOD\n";
    }
  }
}

// The line style of method m: the reference black and thick, the others gnuplot's colours in turn.
std::string style(std::size_t m, const PlotData& data) {
  if (m == data.reference) return "lw 3 pt 7 ps 0.8 lc rgb 'black'";
  // Okabe and Ito's colours (told apart with the common colour blindnesses) less black and yellow, then more.
  static constexpr const char* colours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00",
                                            "#56b4e9", "#882255", "#999933", "#44aa99", "#aa4499"};
  return "lw 1.5 pt " + std::to_string(static_cast<int>(m % 12) + 1) + " ps 0.9 lc rgb '" +
         colours[m % std::size(colours)] + "'";
}

// The error band of the reference (when it has one), then every curve; `column` 2 (A/A0) or 5 (relative).
void write_curves(std::ostream& out, const SceneReport& report, const PlotData& data, int column) {
  out << "plot ";
  bool first = true;
  const auto separator = [&] {
    out << (first ? "" : ", \\\n     ");
    first = false;
  };
  if (data.reference < report.methods.size() &&
      !report.methods[data.reference].curve.area_fraction_error.empty()) {
    separator();
    if (column == 2)
      out << "$method" << data.reference
          << " using 1:3:4 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle";
    else
      out << "$method" << data.reference
          << " using 1:(-$6):6 with filledcurves fc rgb '#b0b0b0' fs transparent solid 0.5 notitle";
  }
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    if (column == 5 && m == data.reference) continue;  // its own relative error is 0
    separator();
    out << "$method" << m << " using 1:" << column << " with linespoints " << style(m, data) << " notitle";
    if (column == 2 && path_column(report.methods[m].curve, "load")) {
      separator();
      out << "$path" << m << " using 1:2 with lines dt 2 " << style(m, data) << " notitle";
    }
  }
  if (column == 5) {
    separator();
    out << "0 with lines lw 1 lc rgb 'black' dt 2 notitle";
  }
  out << '\n';
}

// The legend alone in the fourth panel, off the data: each style with its label, the band, where a method
// stops. Drawn by plotting every style above the panel's range.
void write_legend(std::ostream& out, const SceneReport& report, const PlotData& data) {
  out << "unset title\nset border 0\nunset tics\nunset xlabel\nunset ylabel\nunset logscale\nunset grid\n"
         "set lmargin 0\nset rmargin 0\n"
         "set xrange [0:1]\nset yrange [0:1]\nset key inside left center vertical Left reverse noautotitle "
         "spacing 1.4 width 2\n";
  out << "plot ";
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& method = report.methods[m];
    out << (m == 0 ? "" : ", \\\n     ") << "2 with linespoints " << style(m, data) << " title "
        << gnuplot_lines(method.label + (m == data.reference ? " (reference)" : "") + method.note_suffix() +
                             (method.curve.path_columns.empty() ? "" : "; dashed: its load path"),
                         data.stops[m])
        << " noenhanced";
  }
  if (data.reference < report.methods.size() &&
      !report.methods[data.reference].curve.area_fraction_error.empty())
    out << ", \\\n     2 with filledcurves y1=3 fc rgb '#b0b0b0' fs transparent solid 0.5 title "
        << gnuplot_quote(report.methods[data.reference].label + ": its error estimate (area_fraction_error)")
        << " noenhanced";
  out << '\n';
}

// The four panels: A/A0 on linear axes (as the paper draws them) and log-log (small loads), the relative
// error against the reference, and the legend.
void write_panels(std::ostream& out, const SceneReport& report, const PlotData& data) {
  out << "set multiplot layout 2,2 title "
      << gnuplot_quote(report.scene.name + ": real contact area against load") << " noenhanced\n";
  out << "set key off\nset grid\nset border\nset tics\nset lmargin -1\nset rmargin -1\nset xlabel '"
      << kLoadLabel << "'\n";
  const bool bounded = data.load_max > 0;
  // Linear axes from 0 to the data's largest values.
  out << "unset logscale\nset format x '%g'\nset format y '%g'\nset title '(a) linear axes'\nset ylabel '"
      << kAreaLabel << "'\n";
  out << "set xrange [0:" << (bounded ? gnuplot_number(data.load_max * 1.03) : "*")
      << "]\nset yrange [0:" << (bounded ? gnuplot_number(data.area_max * 1.05) : "*") << "]\n";
  write_curves(out, report, data, 2);
  // Log axes bounded by the data (a tenth of a decade beyond), not gnuplot's whole decades.
  out << "set logscale xy\nset format x '10^{%L}'\nset format y '10^{%L}'\nset title '(b) logarithmic "
         "axes'\n";
  if (bounded)
    out << "set xrange [" << gnuplot_number(data.load_min / 1.26) << ":"
        << gnuplot_number(data.load_max * 1.26) << "]\nset yrange [" << gnuplot_number(data.area_min / 1.26)
        << ":" << gnuplot_number(data.area_max * 1.26) << "]\n";
  else
    out << "set xrange [*:*]\nset yrange [*:*]\n";
  write_curves(out, report, data, 2);
  out << "set logscale x\nunset logscale y\nset format y '%g'\nset yrange [*:*]\nset title '(c) relative "
         "error against the "
         "reference'\nset ylabel '{/:Italic A} / {/:Italic A}_{ref} - 1'\n";
  if (data.reference < report.methods.size())
    write_curves(out, report, data, 5);
  else
    out << "set label 1 'no reference in this scene' at graph 0.5, 0.5 center\nplot 2 notitle\nunset label "
           "1\n";
  write_legend(out, report, data);
  out << "unset multiplot\n";
}

}  // namespace

void write_gnuplot_script(std::ostream& out, const SceneReport& report, const std::string& png,
                          const std::string& svg) {
  out << "# Made by contactbench run (app/load_area_plots.cpp): `gnuplot load_area.gp` in this folder "
         "redraws\n"
         "# the plots; the data blocks below are the curves of curves.csv (load, A/A0, A/A0 -+ its error "
         "estimate,\n# A/A_ref - 1, the reference's relative error estimate).\n";
  const PlotData data = plot_data(report);
  write_data_blocks(out, report, data);
  out << "set terminal pngcairo enhanced size 1400,1000 font ',11'\nset output '" << png << "'\n";
  write_panels(out, report, data);
  out << "set terminal svg enhanced size 1400,1000 dynamic font ',11'\nset output '" << svg << "'\n";
  write_panels(out, report, data);
  out << "unset output\n";
}

bool draw_load_area_plots(const std::filesystem::path& folder, const SceneReport& report,
                          std::ostream& warnings) {
  if (!gnuplot_available()) {
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
