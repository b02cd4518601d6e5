#include "contactbench/bem/fourier_preconditioner.hpp"

#include "contactbench/core/spectrum.hpp"

namespace contactbench {

template <class T>
std::unique_ptr<Convolution<T>> make_fourier_preconditioner(const Grid& grid, Real modulus, int threads) {
  // Non-periodic: the filter of the doubled lattice, on the zero-padded residual (see the header).
  const bool padded = !grid.periodic;
  Grid lattice_grid = grid;
  if (padded) {
    lattice_grid.nx *= 2;
    lattice_grid.ny *= 2;
    lattice_grid.lx *= 2;
    lattice_grid.ly *= 2;
  }
  const HalfLattice lattice(lattice_grid);
  const Eigen::Array<Real, 1, Eigen::Dynamic> qx2 = lattice.qx_row().square();
  const Eigen::Array<Real, Eigen::Dynamic, 1> qy2 = lattice.qy_column().square();
  // (E*/2)|q| with the transform pair's 1/(nx ny) folded in (Convolution::set_multiplier).
  Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> multiplier =
      (qy2.replicate(1, lattice.cols()).rowwise() + qx2).sqrt() *
      (modulus / (2 * static_cast<Real>(lattice_grid.points())));
  multiplier(0, 0) = 0;
  auto convolution = std::make_unique<Convolution<T>>(grid.nx, grid.ny, padded, threads);
  convolution->set_multiplier(multiplier);
  return convolution;
}

template std::unique_ptr<Convolution<double>> make_fourier_preconditioner(const Grid&, Real, int);
template std::unique_ptr<Convolution<float>> make_fourier_preconditioner(const Grid&, Real, int);

}  // namespace contactbench
