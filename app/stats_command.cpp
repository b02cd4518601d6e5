// contactbench stats: a topography's sizes and spectral statistics as one JSON object (docs/theory.md section
// 1).
#include <iostream>
#include <optional>
#include <string>

#include "contactbench/app/cli.hpp"
#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/topography_options.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

struct StatsOptions {
  TopographyOptions topography;
  int threads = 1;
};

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
        "none: heights as stored; mean: mean removed; plane: least-squares plane removed (docs/formats.md)");
  c.add("unit",
        "the unit the file's heights were written in (stated by the file, given with --unit, or m); every "
        "value here is in SI");
  c.add("window", window == Window::hann
                      ? "hann: the surface is not periodic, so it was Hann-windowed before the transform"
                      : "none: the surface is periodic, the lattice sums are exact");
  return c;
}

void run_stats(const StatsOptions& o) {
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
      .add("window", to_string(coefficients.window))
      .add("conventions", conventions(coefficients.window));
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
  command->callback([options] { run_stats(*options); });
}

}  // namespace contactbench
