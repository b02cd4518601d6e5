#include "contactbench/bem/fourier_preconditioner.hpp"

#include "contactbench/core/spectrum.hpp"

namespace contactbench {

namespace {

// (E*/2)|q| with the transform pair's 1/(nx ny) folded in (Convolution::set_multiplier), on the lattice the
// filter runs on: the grid's own when periodic, else the doubled one of the zero-padded residual (see the
// header).
Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> filter_multiplier(const Grid& grid,
                                                                                        Real modulus) {
  const Grid lattice_grid = filter_lattice(grid);
  const HalfLattice lattice(lattice_grid);
  const Eigen::Array<Real, 1, Eigen::Dynamic> qx2 = lattice.qx_row().square();
  const Eigen::Array<Real, Eigen::Dynamic, 1> qy2 = lattice.qy_column().square();
  Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> multiplier =
      (qy2.replicate(1, lattice.cols()).rowwise() + qx2).sqrt() *
      (modulus / (2 * static_cast<Real>(lattice_grid.points())));
  multiplier(0, 0) = 0;
  return multiplier;
}

template <class T>
std::unique_ptr<Convolution<T>> make_filter(
    const Grid& grid, const Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& multiplier,
    int threads, FftRigor rigor) {
  auto convolution = std::make_unique<Convolution<T>>(grid.nx, grid.ny, !grid.periodic, threads, rigor);
  convolution->set_multiplier(multiplier);
  return convolution;
}

}  // namespace

Grid filter_lattice(const Grid& grid) {
  Grid lattice = grid;
  if (!grid.periodic) {
    lattice.nx *= 2;
    lattice.ny *= 2;
    lattice.lx *= 2;
    lattice.ly *= 2;
  }
  return lattice;
}

template <class T>
std::unique_ptr<Convolution<T>> make_fourier_preconditioner(const Grid& grid, Real modulus, int threads) {
  return make_filter<T>(grid, filter_multiplier(grid, modulus), threads, FftRigor::by_work);
}

template <class T>
std::unique_ptr<Convolution<T>> make_unit_fourier_preconditioner(const Grid& grid, int threads,
                                                                 FftRigor rigor) {
  // |q| / max |q| with the pair's normalisation, 1 / the lattice's points, kept.
  auto multiplier = filter_multiplier(grid, 1.0);
  const double peak = multiplier.maxCoeff();
  const double lattice_points = static_cast<double>(grid.points()) * (grid.periodic ? 1 : 4);
  if (peak > 0) multiplier /= peak * lattice_points;  // (a 1 x 1 grid has only the q = 0 mode)
  return make_filter<T>(grid, multiplier, threads, rigor);
}

template std::unique_ptr<Convolution<double>> make_fourier_preconditioner(const Grid&, Real, int);
template std::unique_ptr<Convolution<float>> make_fourier_preconditioner(const Grid&, Real, int);
template std::unique_ptr<Convolution<double>> make_unit_fourier_preconditioner(const Grid&, int, FftRigor);
template std::unique_ptr<Convolution<float>> make_unit_fourier_preconditioner(const Grid&, int, FftRigor);

}  // namespace contactbench
