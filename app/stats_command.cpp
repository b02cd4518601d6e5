// contactbench stats: a topography's sizes and spectral statistics as one JSON object (docs/theory.md section
// 1).
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/line_scan.hpp"
#include "contactbench/core/profile_levelling.hpp"
#include "contactbench/core/profile_statistics.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/topography_io.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {

namespace {

struct StatsOptions {
  TopographyOptions topography;
  int threads = 1;
  std::string psd_file;  // --psd: where the PSD goes as CSV (empty: not written)
};

// The command as typed, for the PSD file's header (the options that change what is read).
std::string psd_command(const StatsOptions& o) {
  const TopographyOptions& t = o.topography;
  std::string command = "contactbench stats " + t.file;
  if (t.unit) command += " --unit " + *t.unit;
  if (t.level != "none") command += " --level " + t.level;
  if (t.size) command += " --size " + format_number(*t.size);
  if (t.size_y) command += " --size-y " + format_number(*t.size_y);
  if (t.periodic) command += " --periodic";
  if (t.channel) command += " --channel " + *t.channel;
  if (t.fill != "none") command += " --fill " + t.fill;
  if (t.crop) command += " --crop " + *t.crop;
  if (t.align_rows != "none") command += " --align-rows " + t.align_rows;
  return command + " --psd " + o.psd_file;
}

// Writes `psd` as CSV under a header of the command, its stamp and what the columns mean.
void write_psd_csv(const StatsOptions& o, const SampledPsd& psd, const std::string& meaning,
                   const std::string& columns) {
  const Provenance provenance = current_provenance(o.threads, psd_command(o));
  write_output(o.psd_file, [&](std::ostream& out) {
    out << "# " << provenance.command << "\n# commit " << provenance.commit << ", " << provenance.date << ", "
        << provenance.machine << "\n# " << meaning << "\n"
        << columns << "\n";
    out.precision(17);
    for (std::size_t k = 0; k < psd.q.size(); ++k)
      out << psd.q[k] << ',' << psd.c[k] << ',' << psd.modes[k] << '\n';
  });
}

JsonObject conventions(Window window) {
  JsonObject c;
  c.add("units", "SI: lengths and sq in m, m0 in m^2, m2 dimensionless, m4 in m^-2");
  c.add("moments",
        "profile (Nayak) moments along x and y, summed over the lattice: m_n = sum_k q^n |hhat_k|^2, mean "
        "removed (docs/theory.md section 1)");
  c.add("alpha", "Nayak bandwidth m0 m4x / m2x^2 of the x profile; alpha_y from the y profile");
  c.add("rms_gradient", "areal sqrt(<|grad h|^2>) = sqrt(m2x + m2y)");
  c.add("sq", "root-mean-square height about the mean, after the levelling named in 'level'");
  c.add("level",
        "none: heights as stored; mean: mean removed; plane, quadratic: least-squares polynomial of degree "
        "1, 2 "
        "removed (docs/formats.md)");
  c.add("crop", "the region read (before filling), and the columns and rows it kept; none: the whole grid");
  c.add("align_rows",
        "what each scan line (row) lost after filling, before level: none, mean, median, linear");
  c.add("unit",
        "the unit the file's heights were written in (stated by the file, given with --unit, or m); every "
        "value here is in SI");
  c.add("window", window == Window::hann
                      ? "hann: the surface is not periodic, so it was Hann-windowed before the transform"
                      : "none: the surface is periodic, the lattice sums are exact");
  return c;
}

// A line scan: the statistics of its profile, no spectrum of a surface (docs/formats.md "line scans").
void run_profile_stats(const StatsOptions& o) {
  TopographyReadOptions options;
  options.unit = o.topography.unit;
  const formats::LineScan scan = formats::read_line_scan(o.topography.file, options);
  // Of the 2-D options only --level applies to a profile (core/profile_levelling.hpp); the others are
  // refused.
  const TopographyOptions& t = o.topography;
  for (const auto& [given, option] :
       {std::pair{t.size || t.size_y, "--size"}, std::pair{t.periodic, "--periodic"},
        std::pair{t.channel.has_value(), "--channel"}, std::pair{t.fill != "none", "--fill"},
        std::pair{t.crop.has_value(), "--crop"}, std::pair{t.align_rows != "none", "--align-rows"}})
    if (given)
      throw InputError(t.file, 0,
                       std::string("is a line scan (one profile along x): ") + option +
                           " is for a 2-D file; a line scan takes --unit and --level only");
  const Levelling level = *parse_levelling(t.level);
  if (!o.psd_file.empty()) check_output_file(o.psd_file, t.file, "--psd");
  ProfileStatistics p;
  std::vector<Real> heights;
  try {
    heights = level_profile(scan.x, scan.heights, level);
    p = profile_statistics(scan.x, heights);
  } catch (const InputError&) {
    throw;
  } catch (const Error& error) {
    throw InputError(o.topography.file, 0, error.what());
  }
  JsonObject conventions;
  conventions.add("units", "SI: lengths, mean and rq in m, m0 in m^2, m2 dimensionless, m4 in m^-2");
  conventions.add(
      "profile",
      "a line scan: one profile h(x), linear between its points; mean, rq, rms_slope and the "
      "moments m0 = rq^2, m2 = rms_slope^2 are integrals along x of that profile; rq_points is the "
      "plain rms of the samples; m4 and alpha only for uniform sampling (second differences)");
  JsonObject json;
  json.add("file", o.topography.file)
      .add("format", "line_scan")
      .add("source", scan.source)
      .add("unit", scan.unit)
      .add("level", std::string(to_string(level)))
      .add("points", p.points)
      .add("length", p.length)
      .add("uniform", p.uniform)
      .add("mean", p.mean)
      .add("rq", p.rq)
      .add("rq_points", p.rq_points)
      .add("rms_slope", p.rms_slope)
      .add("m0", p.m0())
      .add("m2", p.m2());
  if (p.rms_curvature) {
    const Real m4 = *p.rms_curvature * *p.rms_curvature;
    json.add("m4", m4).add("alpha", p.m0() * m4 / (p.m2() * p.m2()));
  }
  if (!o.psd_file.empty()) {
    // The profile's periodogram, Hann-windowed (a scan does not repeat), on the uniform steps it was taken.
    if (!p.uniform)
      throw InputError(t.file, 0,
                       "--psd needs a uniformly sampled scan (every step within 1e-3 of the mean step); this "
                       "one's x are uneven, and its spectrum is not a periodogram");
    const Real step = p.length / static_cast<Real>(p.points - 1);
    const Grid grid{
        .nx = p.points, .ny = 1, .lx = step * static_cast<Real>(p.points), .ly = step, .periodic = false};
    const Surface profile(grid, Eigen::Map<const HeightMap>(heights.data(), 1, p.points));
    write_psd_csv(o, profile_psd_x(fourier_coefficients(profile, Window::hann, 1)),
                  "the profile PSD C1(q) [m^3], two-sided (rq^2 = sum over q of C1 dq, q from -qmax to qmax; "
                  "listed for q >= 0), Hann-windowed; modes: points behind each value",
                  "q_per_m,c1_m3,modes");
    json.add("psd_file", o.psd_file);
  }
  json.add("conventions", conventions);
  std::cout << json.str() << '\n';
}

void run_stats(const StatsOptions& o) {
  if (detect_topography_format(o.topography.file) == TopographyFormat::line_scan) return run_profile_stats(o);
  if (!o.psd_file.empty()) check_output_file(o.psd_file, o.topography.file, "--psd");
  const TopographyReading reading = o.topography.read_with_report();
  const Surface& surface = reading.surface;
  // Moments of 1e300 m heights would be printed as null; a failure here is the file's, so it names the file.
  std::optional<FourierCoefficients> transformed;
  std::optional<SpectralMoments> moments;
  try {
    check_summable_heights(surface);
    transformed = fourier_coefficients(surface, o.threads);
    moments = spectral_moments(*transformed);
  } catch (const InputError&) {
    throw;
  } catch (const Error& error) {
    throw InputError(o.topography.file, 0, error.what());
  }
  const FourierCoefficients& coefficients = *transformed;
  const SpectralMoments& m = *moments;
  const Grid& g = surface.grid();

  JsonObject json;
  json.add("file", o.topography.file)
      .add("format", to_string(reading.format))
      .add("channel", reading.channel)
      .add("invalid_points_filled", reading.invalid_points)
      .add("fill", to_string(reading.fill))
      .add("level", to_string(reading.level))
      .add("unit", reading.unit)
      .add("crop", reading.crop)
      .add("align_rows", to_string(reading.align_rows))
      .add("nx", g.nx)
      .add("ny", g.ny)
      .add("lx", g.lx)
      .add("ly", g.ly)
      .add("periodic", g.periodic)
      .add("mean", surface.mean_height())
      .add("sq", surface.rms_height())
      .add("m0", m.m0)
      .add("m2x", m.m2x)
      .add("m4x", m.m4x)
      .add("m2y", m.m2y)
      .add("m4y", m.m4y)
      .add("alpha", m.alpha_x())
      .add("alpha_y", m.alpha_y())
      .add("rms_gradient", m.rms_gradient())
      .add("window", to_string(coefficients.window));
  if (!o.psd_file.empty()) {
    write_psd_csv(
        o, radial_psd(coefficients),
        "the radially averaged 2D PSD C(q) [m^4] (Persson's convention: <h^2> = sum over the lattice "
        "of C dqx dqy), " +
            std::string(to_string(coefficients.window)) +
            " window, 10 bins a decade; q: the bin's mean |q|; modes: lattice modes in the bin",
        "q_per_m,c_m4,modes");
    json.add("psd_file", o.psd_file);
  }
  json.add("conventions", conventions(coefficients.window));
  std::cout << json.str() << '\n';
}

}  // namespace

void add_stats_command(CLI::App& parent) {
  auto options = std::make_shared<StatsOptions>();
  CLI::App* command = parent.add_subcommand(
      "stats", "Print a topography's sizes, Sq and spectral moments as one JSON object (SI units). Reads " +
                   readable_formats_help() + ".");
  options->topography.add_to(*command, "moments without a window");
  add_threads_option(*command, options->threads);
  command->add_option("--psd", options->psd_file,
                      "also write the PSD as CSV to this file: a surface's radially averaged 2D PSD C(q) "
                      "[m^4], a line scan's profile PSD C1(q) [m^3] (uniform sampling only)");
  command->callback([options] { run_stats(*options); });
}

}  // namespace contactbench
