#include "contactbench/mpi/distributed_half_space.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "contactbench/bem/fourier_preconditioner.hpp"
#include "contactbench/bem/love_kernel.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench::mpi {

namespace {

void check_operator(const Grid& grid, Real modulus) {
  validate(grid, "distributed half-space grid");
  if (!(std::isfinite(modulus) && modulus > 0))
    throw Error("half-space: the modulus E* must be finite and > 0 Pa, got " + std::to_string(modulus));
}

// factor * |q| ^ power on this rank's spectral columns of `lattice_grid` (q = 0 gives 0).
std::vector<double> radial_multiplier(DistributedConvolution& convolution, const Grid& lattice_grid,
                                      Real factor, int power) {
  const HalfLattice lattice(lattice_grid);
  const Index ly = convolution.ly();
  std::vector<double> multiplier(static_cast<std::size_t>(convolution.spectrum_count() * ly));
  for (Index c = 0; c < convolution.spectrum_count(); ++c)
    for (Index row = 0; row < ly; ++row) {
      const Real qx = lattice.qx(convolution.spectrum_start() + c), qy = lattice.qy(row);
      const Real q = std::sqrt(qy * qy + qx * qx);
      multiplier[static_cast<std::size_t>(c * ly + row)] = q > 0 ? factor * std::pow(q, power) : 0.0;
    }
  return multiplier;
}

// Love's kernel on the doubled lattice, offsets wrapped (bem/half_space.cpp), transformed by the
// convolution's own transform; the kernel is even, so its transform is real. The pair's 1/(4 nx ny) is folded
// in.
std::vector<double> love_multiplier(DistributedConvolution& convolution, const Grid& grid, Real modulus) {
  const Index nx = grid.nx, ny = grid.ny;
  const Real dx = grid.dx(), dy = grid.dy();
  DistributedRealFft2d& fft = convolution.transform();
  const Slab& slab = fft.slab();
  for (Index r = 0; r < slab.count; ++r) {
    const Index iy = slab.start + r;
    double* row = fft.real_row(r);
    for (Index ix = 0; ix < 2 * nx; ++ix) {
      const Real x = static_cast<Real>(ix < nx ? ix : ix - 2 * nx) * dx;
      const Real y = static_cast<Real>(iy < ny ? iy : iy - 2 * ny) * dy;
      row[ix] = love_displacement(x, y, dx / 2, dy / 2) / modulus;
    }
  }
  fft.forward();
  const Complex* spectrum = fft.spectrum();
  std::vector<double> multiplier(static_cast<std::size_t>(fft.spectrum_count() * 2 * ny));
  for (std::size_t i = 0; i < multiplier.size(); ++i)
    multiplier[i] = spectrum[i].real() / static_cast<Real>(4 * nx * ny);
  return multiplier;
}

}  // namespace

DistributedHalfSpace::DistributedHalfSpace(const Grid& grid, Real modulus, MPI_Comm comm, int threads)
    : grid_(grid) {
  check_operator(grid, modulus);
  convolution_ = std::make_unique<DistributedConvolution>(grid, !grid.periodic, comm, threads);
  // Periodic: 2/(E* |q|) with the pair's 1/(nx ny) folded in, 0 at q = 0 (bem/half_space.cpp).
  convolution_->set_multiplier(
      grid.periodic
          ? radial_multiplier(*convolution_, grid, 2 / (modulus * static_cast<Real>(grid.points())), -1)
          : love_multiplier(*convolution_, grid, modulus));
}

std::unique_ptr<DistributedConvolution> make_distributed_preconditioner(const Grid& grid, Real modulus,
                                                                        MPI_Comm comm, int threads) {
  check_operator(grid, modulus);
  const bool padded = !grid.periodic;
  const Grid lattice_grid = filter_lattice(grid);
  auto convolution = std::make_unique<DistributedConvolution>(grid, padded, comm, threads);
  // (E*/2)|q| with the pair's 1/(lx ly) folded in (bem/fourier_preconditioner.cpp).
  convolution->set_multiplier(radial_multiplier(*convolution, lattice_grid,
                                                modulus / (2 * static_cast<Real>(lattice_grid.points())), 1));
  return convolution;
}

std::unique_ptr<DistributedConvolution> make_distributed_unit_preconditioner(
    const Grid& grid, MPI_Comm comm, int threads, const DistributedConvolution* share,
    bool single_precision) {
  validate(grid, "distributed filter grid");
  const bool padded = !grid.periodic;
  const Grid lattice_grid = filter_lattice(grid);
  auto convolution =
      std::make_unique<DistributedConvolution>(grid, padded, comm, threads, share, single_precision);
  // |q| / max |q| with the pair's normalisation: the serial filter's arithmetic
  // (bem/fourier_preconditioner.cpp, (1/2)|q| / (points) first, then divided by its peak times the lattice's
  // points).
  const double lattice_points = static_cast<double>(lattice_grid.points());
  std::vector<double> multiplier =
      radial_multiplier(*convolution, lattice_grid, 1.0 / (2 * lattice_points), 1);
  double peak = multiplier.empty() ? 0.0 : *std::max_element(multiplier.begin(), multiplier.end());
  MPI_Allreduce(MPI_IN_PLACE, &peak, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (peak > 0)
    for (double& m : multiplier)
      m /= peak * lattice_points;
  convolution->set_multiplier(std::move(multiplier));
  return convolution;
}

}  // namespace contactbench::mpi
