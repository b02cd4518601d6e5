#include "contactbench/core/generation.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/memory_budget.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

namespace {

// SplitMix64 (Steele, Lea, Flood 2014): a strong 64-bit mixer, used as a counter-based random source.
std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// A uniform phase in [0, 2 pi) for the mode pair {k, -k}, keyed by its representative with kx > 0, or kx = 0
// and ky > 0; the other member of the pair gets the opposite phase (docs/theory.md section 2: phi_{-k} =
// -phi_k).
Real random_phase(std::uint64_t seed, Index kx, Index ky) {
  Real sign = 1;
  if (kx < 0 || (kx == 0 && ky < 0)) {
    kx = -kx;
    ky = -ky;
    sign = -1;
  }
  const std::uint64_t key = splitmix64(splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(kx)) ^
                                       static_cast<std::uint64_t>(ky));
  const Real uniform = static_cast<Real>(key >> 11) * 0x1.0p-53;  // 53 random bits in [0, 1)
  return sign * 2 * std::numbers::pi * uniform;
}

std::string str(Real value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", value);
  return buffer;
}

}  // namespace

void validate(const SelfAffinePsd& psd, const Grid& grid) {
  validate(grid, "generation grid");
  auto positive = [](Real v) { return std::isfinite(v) && v > 0; };
  if (!positive(psd.sigma)) throw Error("sigma must be a finite rms height > 0 m, got " + str(psd.sigma));
  if (!(std::isfinite(psd.hurst) && psd.hurst > 0 && psd.hurst <= 1))
    throw Error("hurst must lie in (0, 1], got " + str(psd.hurst));
  if (!positive(psd.qr)) throw Error("qr must be a finite wavevector > 0 1/m, got " + str(psd.qr));
  if (!positive(psd.anisotropy)) throw Error("anisotropy (m2x/m2y) must be > 0, got " + str(psd.anisotropy));
  const Real qs = psd.cutoff(grid);
  // A cut above Nyquist would be a square cut by the lattice, not the radial cut the model asks for.
  if (!positive(qs) || qs > grid.nyquist() * (1 + 1e-9))
    throw Error("qs must lie in (0, " + str(grid.nyquist()) +
                "] 1/m (the grid's Nyquist wavevector pi/dx), got " + str(qs) +
                ": refine the grid or lower qs");
  if (psd.qr >= qs)
    throw Error("qr = " + str(psd.qr) + " 1/m must lie below qs = " + str(qs) +
                " 1/m: the roll-off comes before the cut-off (docs/theory.md section 2)");
  if (qs < std::min(grid.dqx(), grid.dqy()))
    throw Error("qs = " + str(qs) + " 1/m lies below the smallest wavevector of the lattice (" +
                str(std::min(grid.dqx(), grid.dqy())) + " 1/m): no mode would carry height");
}

SelfAffineModes::SelfAffineModes(const Grid& grid, const SelfAffinePsd& psd)
    : lattice_(grid),
      qr_(psd.qr),
      qs_(psd.cutoff(grid)),
      gx_(std::min(1.0, std::sqrt(psd.anisotropy))),
      gy_(std::min(1.0, 1 / std::sqrt(psd.anisotropy))),
      exponent_(-2 * (1 + psd.hurst)) {
  validate(psd, grid);
  const HalfLattice& lattice = lattice_;
  // Shape of the PSD (C0 = 1) on the half lattice, then its lattice sum (each entry counted with its mirror).
  using RealMap = Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RealMap shape_map(lattice.rows(), lattice.cols());
  for (Index row = 0; row < lattice.rows(); ++row)
    for (Index col = 0; col < lattice.cols(); ++col)
      shape_map(row, col) = shape(row, col);
  const Real lattice_sum = (shape_map.rowwise() * lattice.multiplicity_row()).sum();
  if (!(lattice_sum > 0)) {
    // Every mode's power underflowed: the lattice starts so far above the roll-off that (q/qr)^(-2(1+H))
    // is below double precision there (a lateral size of 1e-300 m with qr = 1e5 1/m, say).
    const Real lowest = std::min(grid.dqx(), grid.dqy());
    throw Error("the PSD leaves no lattice mode with height: the lattice's lowest wavevector 2 pi/L = " +
                str(lowest) + " 1/m (lateral size " + str(std::max(grid.lx, grid.ly)) + " m) is " +
                str(lowest / psd.qr) + " times the roll-off qr = " + str(psd.qr) +
                " 1/m, where the spectrum's power (q/qr)^(-2(1+H)) is below double precision's range (qs = " +
                str(qs_) + " 1/m): choose qr near or above 2 pi/L, or a larger lateral size");
  }
  // |hhat_k|^2 = C_k dqx dqy with sum_k C_k dqx dqy = sigma^2 (normalised on the lattice).
  scale_ = psd.sigma / std::sqrt(lattice_sum);
}

Real SelfAffineModes::shape(Index row, Index col) const {
  const HalfLattice& lattice = lattice_;
  const Real q = std::hypot(lattice.qx(col) / gx_, lattice.qy(row) / gy_);
  const bool excluded = (row == 0 && col == 0) || lattice.nyquist_row(row) || lattice.nyquist_col(col);
  return (excluded || q > qs_) ? 0.0 : (q < qr_ ? 1.0 : std::pow(q / qr_, exponent_));
}

Complex SelfAffineModes::coefficient(Index row, Index col, std::uint64_t seed) const {
  return std::polar(scale_ * std::sqrt(shape(row, col)),
                    random_phase(seed, lattice_.kx(col), lattice_.ky(row)));
}

SpectrumMap generate_coefficients(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed) {
  validate(psd, grid);
  // The half spectrum (16 B per value) and the shape's sum (8 B), about half the points each: 12 B per point.
  check_fits_in_memory(
      saturating_product(
          saturating_product(static_cast<std::uintmax_t>(grid.nx), static_cast<std::uintmax_t>(grid.ny)), 12),
      "the spectrum of a " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " grid");
  const SelfAffineModes modes(grid, psd);
  const HalfLattice lattice(grid);
  SpectrumMap hhat(lattice.rows(), lattice.cols());
  for (Index row = 0; row < lattice.rows(); ++row)
    for (Index col = 0; col < lattice.cols(); ++col)
      hhat(row, col) = modes.coefficient(row, col, seed);
  return hhat;
}

Surface generate_surface(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed, int threads) {
  return synthesize(grid, generate_coefficients(grid, psd, seed), grid.nx, grid.ny, threads);
}

Surface synthesize(const Grid& grid, const SpectrumMap& hhat, Index nx, Index ny, int threads) {
  validate(grid, "synthesis grid");
  if (nx < grid.nx || ny < grid.ny)
    throw Error("Fourier interpolation goes to a finer grid only: asked for " + std::to_string(nx) + " x " +
                std::to_string(ny) + " from " + std::to_string(grid.nx) + " x " + std::to_string(grid.ny));
  const HalfLattice source(grid);
  if (hhat.rows() != source.rows() || hhat.cols() != source.cols())
    throw Error("synthesis: coefficient array does not match the grid");
  // The embedded half spectrum (16 B per complex value, half the points) and the heights (8 B), with the
  // FFT's work in place: about 16 B per point of the output grid.
  check_fits_in_memory(
      saturating_product(saturating_product(static_cast<std::uintmax_t>(nx), static_cast<std::uintmax_t>(ny)),
                         16),
      "a surface of " + std::to_string(nx) + " x " + std::to_string(ny) + " points");
  const bool split_column = nx > grid.nx, split_row = ny > grid.ny;

  // Embed the coefficients in the larger lattice at the same (kx, ky): the same function, sampled finer.
  SpectrumMap embedded = SpectrumMap::Zero(ny, nx / 2 + 1);
  for (Index row = 0; row < source.rows(); ++row) {
    const Index ky = source.ky(row);
    for (Index col = 0; col < source.cols(); ++col) {
      Complex value = hhat(row, col);
      // The Nyquist mode of the source stands for +k and -k at once; on a larger lattice they are two
      // modes, each taking half (the column's -kx half is implied by Hermitian symmetry).
      if (split_column && source.nyquist_col(col)) value *= 0.5;
      if (split_row && source.nyquist_row(row)) {
        embedded(ny + ky, col) += 0.5 * value;  // ky = -ny_source/2
        embedded(-ky, col) += 0.5 * value;      // ky = +ny_source/2
      } else {
        embedded((ky + ny) % ny, col) += value;
      }
    }
  }
  HeightMap heights;
  ReproducibleInverseFft2d(nx, ny).backward(embedded, heights, threads);
  Grid fine = grid;
  fine.nx = nx;
  fine.ny = ny;
  fine.periodic = true;
  return Surface(fine, std::move(heights));
}

Surface refine(const Surface& surface, Index nx, Index ny, int threads) {
  if (!surface.grid().periodic)
    throw Error("refine: Fourier interpolation assumes a periodic surface; this one is not periodic");
  const Real mean = surface.mean_height();
  FourierCoefficients c = fourier_coefficients(surface, Window::none, threads);
  c.hhat(0, 0) = mean;  // keep the mean, which fourier_coefficients removes
  return synthesize(surface.grid(), c.hhat, nx, ny, threads);
}

namespace paper {
Grid grid() {
  return Grid{.nx = 256, .ny = 256, .lx = 200e-6, .ly = 200e-6, .periodic = true};
}
SelfAffinePsd surface_a() {
  return {.sigma = 0.5e-6, .hurst = 0.5, .qr = 3.14e4, .qs = std::nullopt};
}
SelfAffinePsd surface_b() {
  return {.sigma = 1.0e-6, .hurst = 0.8, .qr = 1.00e5, .qs = std::nullopt};
}
SelfAffinePsd surface_b_printed_qs() {
  return {.sigma = 1.0e-6, .hurst = 0.8, .qr = 1.00e5, .qs = 3.00e6};
}
}  // namespace paper

}  // namespace contactbench
