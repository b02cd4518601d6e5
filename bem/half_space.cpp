#include "contactbench/bem/half_space.hpp"

#include <cmath>
#include <string>

#include "contactbench/bem/love_kernel.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/formats/text_values.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

namespace {

using DoubleMap = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void check_shape(const Grid& grid, const HeightMap& pressure) {
  if (pressure.rows() != grid.ny || pressure.cols() != grid.nx)
    throw Error("half-space: the pressure is " + std::to_string(pressure.cols()) + " x " +
                std::to_string(pressure.rows()) + " (x by y) but the operator's grid is " +
                std::to_string(grid.nx) + " x " + std::to_string(grid.ny));
}

void check_operator(const Grid& grid, Real modulus) {
  validate(grid, "half-space grid");
  if (!(std::isfinite(modulus) && modulus > 0))
    throw Error("half-space: the modulus E* must be finite and > 0 Pa, got " + formats::format_real(modulus));
}

// 2/(E* |q|) with the FFT pair's normalisation 1/(nx ny) folded in; 0 at q = 0.
DoubleMap periodic_multiplier(const Grid& grid, Real modulus) {
  const HalfLattice lattice(grid);
  const Eigen::Array<Real, 1, Eigen::Dynamic> qx2 = lattice.qx_row().square();
  const Eigen::Array<Real, Eigen::Dynamic, 1> qy2 = lattice.qy_column().square();
  DoubleMap multiplier = (qy2.replicate(1, lattice.cols()).rowwise() + qx2).sqrt().inverse() *
                         (2 / (modulus * static_cast<Real>(grid.points())));
  multiplier(0, 0) = 0;
  return multiplier;
}

// Love's kernel on the doubled lattice, offsets wrapped so that index i stands for i or i - 2n; the offset n
// itself is never needed by a convolution of n points (largest offset n - 1). The kernel is even in x and y,
// so its transform is real (and even); the FFT pair's 1/(4 nx ny) is folded in.
DoubleMap nonperiodic_multiplier(const Grid& grid, Real modulus) {
  const Index nx = grid.nx, ny = grid.ny;
  const Real dx = grid.dx(), dy = grid.dy();
  RealFft2d fft(2 * nx, 2 * ny);
  auto kernel = fft.real();
  for (Index iy = 0; iy < 2 * ny; ++iy)
    for (Index ix = 0; ix < 2 * nx; ++ix) {
      const Real x = static_cast<Real>(ix < nx ? ix : ix - 2 * nx) * dx;
      const Real y = static_cast<Real>(iy < ny ? iy : iy - 2 * ny) * dy;
      kernel(iy, ix) = love_displacement(x, y, dx / 2, dy / 2) / modulus;
    }
  fft.forward();
  return fft.spectrum().real() / static_cast<Real>(4 * nx * ny);
}

class FftHalfSpace final : public HalfSpace {
 public:
  FftHalfSpace(const Grid& grid, Real modulus, int threads, bool periodic)
      : HalfSpace(grid, modulus), convolution_(grid.nx, grid.ny, !periodic, threads) {
    convolution_.set_multiplier(periodic ? periodic_multiplier(grid, modulus)
                                         : nonperiodic_multiplier(grid, modulus));
  }

  void apply(const HeightMap& pressure, HeightMap& displacement) override {
    check_shape(grid(), pressure);
    if (&displacement != &pressure) displacement.resize(grid().ny, grid().nx);
    convolution_.apply(pressure.data(), displacement.data());
  }

  void apply(const Real* pressure, Real* displacement) override {
    convolution_.apply(pressure, displacement);
  }

 private:
  Convolution<Real> convolution_;
};

}  // namespace

HalfSpace::HalfSpace(const Grid& grid, Real modulus) : grid_(grid), modulus_(modulus) {
  check_operator(grid, modulus);
}

std::unique_ptr<HalfSpace> make_periodic_half_space(const Grid& grid, Real modulus, int threads) {
  check_operator(grid, modulus);
  return std::make_unique<FftHalfSpace>(grid, modulus, threads, true);
}

std::unique_ptr<HalfSpace> make_nonperiodic_half_space(const Grid& grid, Real modulus, int threads) {
  check_operator(grid, modulus);
  return std::make_unique<FftHalfSpace>(grid, modulus, threads, false);
}

std::unique_ptr<HalfSpace> make_half_space(const Grid& grid, Real modulus, int threads) {
  return grid.periodic ? make_periodic_half_space(grid, modulus, threads)
                       : make_nonperiodic_half_space(grid, modulus, threads);
}

template <class T>
std::unique_ptr<Convolution<T>> make_half_space_convolution(const Grid& grid, Real modulus, int threads,
                                                            FftRigor rigor) {
  check_operator(grid, modulus);
  auto convolution = std::make_unique<Convolution<T>>(grid.nx, grid.ny, !grid.periodic, threads, rigor);
  convolution->set_multiplier(grid.periodic ? periodic_multiplier(grid, modulus)
                                            : nonperiodic_multiplier(grid, modulus));
  return convolution;
}

template std::unique_ptr<Convolution<double>> make_half_space_convolution(const Grid&, Real, int, FftRigor);
template std::unique_ptr<Convolution<float>> make_half_space_convolution(const Grid&, Real, int, FftRigor);

}  // namespace contactbench
