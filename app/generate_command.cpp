// contactbench generate: the paper's random self-affine surface (docs/theory.md section 2), written to a
// file.
#include <charconv>
#include <cstdint>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>

#include "contactbench/app/cli.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {

namespace {

struct GenerateOptions {
  SelfAffinePsd psd;
  Real size = 0;
  std::optional<Real> size_y;
  Index grid = 0;
  std::optional<Index> grid_y;
  std::uint64_t seed = 1;
  std::optional<Index> refine;
  std::optional<Index> refine_y;
  std::string out;
  int threads = 1;
};

// CLI11 would read "-1" as 2^64 - 1 and clamp 2^64 to it: a seed is taken only as written, digits only.
std::string whole_number_seed(const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || error != std::errc() || end != text.data() + text.size())
    return "a whole number in [0, 18446744073709551615] (2^64 - 1), got '" + text + "'";
  return "";
}

void run_generate(const GenerateOptions& o) {
  const Grid grid{.nx = o.grid,
                  .ny = o.grid_y.value_or(o.grid),
                  .lx = o.size,
                  .ly = o.size_y.value_or(o.size),
                  .periodic = true};
  const SpectrumMap hhat = generate_coefficients(grid, o.psd, o.seed);
  // --refine resamples the same realisation (its coefficients) on a finer grid, never a new realisation.
  const Index nx = o.refine.value_or(grid.nx);
  const Index ny = o.refine_y.value_or(o.refine.value_or(grid.ny));
  const Surface surface = synthesize(grid, hhat, nx, ny, o.threads);
  write_topography(o.out, surface);  // the extension picks the format, as convert's OUT
  std::cerr << "contactbench: wrote " << o.out << " (" << surface.nx() << " x " << surface.ny() << " points, "
            << grid.lx << " x " << grid.ly << " m, seed " << o.seed << ", Sq " << surface.rms_height()
            << " m)\n";
}

}  // namespace

void add_generate_command(CLI::App& parent) {
  auto options = std::make_shared<GenerateOptions>();
  CLI::App* command = parent.add_subcommand(
      "generate",
      "Generate a periodic self-affine rough surface: the paper's generator (deterministic PSD modulus, "
      "random phase, roll-off below qr, radial cut at qs, normalised on the lattice). SI units.");
  command->add_option("--sigma", options->psd.sigma, "rms height [m]")->required();
  command->add_option("--hurst", options->psd.hurst, "Hurst exponent H in (0, 1]")->required();
  command->add_option("--qr", options->psd.qr, "roll-off wavevector [1/m]")->required();
  command->add_option("--qs", options->psd.qs,
                      "cut-off wavevector [1/m] (default: the Nyquist wavevector pi/dx of --grid)");
  command->add_option("--size", options->size, "lateral size along x [m]")->required();
  command->add_option("--size-y", options->size_y, "lateral size along y [m] (default: --size)");
  command->add_option("--grid", options->grid, "points along x")->required()->check(CLI::Range(1, 1 << 16));
  command->add_option("--grid-y", options->grid_y, "points along y (default: --grid)")
      ->check(CLI::Range(1, 1 << 16));
  command->add_option("--seed", options->seed, "random seed, a whole number in [0, 2^64 - 1] (default 1)")
      ->check(whole_number_seed);
  command
      ->add_option("--refine", options->refine,
                   "write the same realisation resampled on M x M points (Fourier interpolation)")
      ->check(CLI::Range(1, 1 << 16));
  command->add_option("--refine-y", options->refine_y, "points along y when refining (default: --refine)")
      ->check(CLI::Range(1, 1 << 16));
  command->add_option("--anisotropy", options->psd.anisotropy, "requested m2x/m2y (default 1: isotropic)");
  command
      ->add_option("--out", options->out,
                   "output file; its extension picks the format: .x3p (ISO 25178-72, float64), .npy "
                   "(float64; carries no lateral size, give --size when reading it) or, for any other, "
                   "the project's lossless text format")
      ->required();
  add_threads_option(*command, options->threads);
  command->callback([options] { run_generate(*options); });
}

}  // namespace contactbench
