#include "contactbench/mpi/distributed_generation.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/mpi/distributed_fft.hpp"
#include "contactbench/mpi/distributed_synthesis.hpp"

namespace contactbench::mpi {

HeightMap generate_surface_slab(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed,
                                MPI_Comm comm) {
  // Validates, and sums the normalisation over the whole half lattice as the serial generator does.
  const SelfAffineModes modes(grid, psd);
  // Each coefficient added to zero, as the serial generator embeds them (core/generation.cpp, synthesize).
  const auto coefficients = [&](Index first, Index width, Complex* block) {
    for (Index row = 0; row < grid.ny; ++row)
      for (Index j = 0; j < width; ++j) {
        Complex value(0.0, 0.0);
        value += modes.coefficient(row, first + j, seed);
        block[row * width + j] = value;
      }
  };
  return synthesize_slab(grid.nx, grid.ny, coefficients, comm);
}

SpectralMoments distributed_spectral_moments(const Grid& grid, const HeightMap& local_heights,
                                             MPI_Comm comm) {
  validate(grid, "distributed moments grid");
  DistributedRealFft2d fft(grid.nx, grid.ny, comm);
  const Slab& slab = fft.slab();
  throw_on_any_rank(local_heights.rows() != slab.count || local_heights.cols() != grid.nx,
                    "mpi: moments: the local heights are " + std::to_string(local_heights.cols()) + " x " +
                        std::to_string(local_heights.rows()) + " but this rank's slab is " +
                        std::to_string(grid.nx) + " x " + std::to_string(slab.count),
                    comm);
  const Real mean = sum_over_ranks(local_heights.sum(), comm) / static_cast<Real>(grid.points());
  // The Hann window of core/spectrum.cpp, sin^2(pi (i + 1/2) / n), separable and normalised by its rms.
  auto hann = [](Index i, Index n) {
    const Real s = std::sin(std::numbers::pi * (static_cast<Real>(i) + 0.5) / static_cast<Real>(n));
    return s * s;
  };
  const bool windowed = default_window(grid) == Window::hann;
  Real rms_window = 1;
  if (windowed) {
    Real sx = 0, sy = 0;
    for (Index i = 0; i < grid.nx; ++i)
      sx += hann(i, grid.nx) * hann(i, grid.nx);
    for (Index i = 0; i < grid.ny; ++i)
      sy += hann(i, grid.ny) * hann(i, grid.ny);
    rms_window = std::sqrt(sx / static_cast<Real>(grid.nx) * (sy / static_cast<Real>(grid.ny)));
  }
  for (Index r = 0; r < slab.count; ++r) {
    double* row = fft.real_row(r);
    const Real wy = windowed ? hann(slab.start + r, grid.ny) : 1.0;
    for (Index x = 0; x < grid.nx; ++x)
      row[x] = (local_heights(r, x) - mean) * (windowed ? wy * hann(x, grid.nx) / rms_window : 1.0);
  }
  fft.forward();

  // Sums over this rank's spectral columns (each weighted by the full-lattice modes it stands for), then
  // over the ranks. The mean (k = 0) is excluded, as in the serial moments.
  const HalfLattice lattice(grid);
  const Real norm = static_cast<Real>(grid.points());
  double sums[5] = {0, 0, 0, 0, 0};  // m0, m2x, m4x, m2y, m4y
  const Complex* spectrum = fft.spectrum();
  for (Index c = 0; c < fft.spectrum_count(); ++c) {
    const Index col = fft.spectrum_start() + c;
    const Real qx2 = lattice.qx(col) * lattice.qx(col), weight = lattice.multiplicity(col);
    for (Index row = 0; row < grid.ny; ++row) {
      if (row == 0 && col == 0) continue;
      const Real power = weight * std::norm(spectrum[c * grid.ny + row] / norm);
      const Real qy2 = lattice.qy(row) * lattice.qy(row);
      sums[0] += power;
      sums[1] += power * qx2;
      sums[2] += power * qx2 * qx2;
      sums[3] += power * qy2;
      sums[4] += power * qy2 * qy2;
    }
  }
  double totals[5];
  MPI_Allreduce(sums, totals, 5, MPI_DOUBLE, MPI_SUM, comm);
  SpectralMoments m;
  m.m0 = totals[0];
  m.m2x = totals[1];
  m.m4x = totals[2];
  m.m2y = totals[3];
  m.m4y = totals[4];
  return m;
}

}  // namespace contactbench::mpi
