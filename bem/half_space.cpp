#include "bem/half_space.hpp"

#include <cmath>
#include <string>

#include "bem/love_kernel.hpp"
#include "core/error.hpp"
#include "core/fft.hpp"
#include "core/spectrum.hpp"

namespace contactbench {

namespace {

using RealMap = Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

void check_shape(const Grid& grid, const HeightMap& pressure) {
  if (pressure.rows() != grid.ny || pressure.cols() != grid.nx)
    throw Error("half-space: the pressure is " + std::to_string(pressure.cols()) + " x " +
                std::to_string(pressure.rows()) + " (x by y) but the operator's grid is " +
                std::to_string(grid.nx) + " x " + std::to_string(grid.ny));
}

class PeriodicHalfSpace final : public HalfSpace {
 public:
  PeriodicHalfSpace(const Grid& grid, Real modulus, int threads)
      : HalfSpace(grid, modulus), fft_(grid.nx, grid.ny, threads) {
    // 2/(E* |q|) with the FFT pair's normalisation 1/(nx ny) folded in; 0 at q = 0.
    const HalfLattice lattice(grid);
    const Eigen::Array<Real, 1, Eigen::Dynamic> qx2 = lattice.qx_row().square();
    const Eigen::Array<Real, Eigen::Dynamic, 1> qy2 = lattice.qy_column().square();
    multiplier_ = (qy2.replicate(1, lattice.cols()).rowwise() + qx2).sqrt().inverse() *
                  (2 / (modulus * static_cast<Real>(grid.points())));
    multiplier_(0, 0) = 0;
  }

  void apply(const HeightMap& pressure, HeightMap& displacement) override {
    check_shape(grid(), pressure);
    fft_.real() = pressure;
    fft_.forward();
    fft_.spectrum() *= multiplier_;
    fft_.backward();
    displacement = fft_.real();
  }

 private:
  RealFft2d fft_;
  RealMap multiplier_;
};

class NonPeriodicHalfSpace final : public HalfSpace {
 public:
  NonPeriodicHalfSpace(const Grid& grid, Real modulus, int threads)
      : HalfSpace(grid, modulus), fft_(2 * grid.nx, 2 * grid.ny, threads) {
    // Love's kernel on the doubled lattice, offsets wrapped so that index i stands for i or i - 2n; the
    // offset n itself is never needed by a convolution of n points (largest offset n - 1).
    const Index nx = grid.nx, ny = grid.ny;
    const Real dx = grid.dx(), dy = grid.dy();
    auto kernel = fft_.real();
    for (Index iy = 0; iy < 2 * ny; ++iy)
      for (Index ix = 0; ix < 2 * nx; ++ix) {
        const Real x = static_cast<Real>(ix < nx ? ix : ix - 2 * nx) * dx;
        const Real y = static_cast<Real>(iy < ny ? iy : iy - 2 * ny) * dy;
        kernel(iy, ix) = love_displacement(x, y, dx / 2, dy / 2) / modulus;
      }
    fft_.forward();
    // The kernel is even in x and y, so its transform is real; the FFT pair's 1/(4 nx ny) is folded in.
    kernel_spectrum_ = fft_.spectrum().real() / static_cast<Real>(4 * nx * ny);
  }

  void apply(const HeightMap& pressure, HeightMap& displacement) override {
    check_shape(grid(), pressure);
    const Index nx = grid().nx, ny = grid().ny;
    auto padded = fft_.real();
    padded.setZero();
    padded.topLeftCorner(ny, nx) = pressure;
    fft_.forward();
    fft_.spectrum() *= kernel_spectrum_;
    fft_.backward();
    displacement = fft_.real().topLeftCorner(ny, nx);
  }

 private:
  RealFft2d fft_;
  RealMap kernel_spectrum_;
};

}  // namespace

HalfSpace::HalfSpace(const Grid& grid, Real modulus) : grid_(grid), modulus_(modulus) {
  validate(grid, "half-space grid");
  if (!(std::isfinite(modulus) && modulus > 0))
    throw Error("half-space: the modulus E* must be finite and > 0 Pa, got " + std::to_string(modulus));
}

std::unique_ptr<HalfSpace> make_periodic_half_space(const Grid& grid, Real modulus, int threads) {
  return std::make_unique<PeriodicHalfSpace>(grid, modulus, threads);
}

std::unique_ptr<HalfSpace> make_nonperiodic_half_space(const Grid& grid, Real modulus, int threads) {
  return std::make_unique<NonPeriodicHalfSpace>(grid, modulus, threads);
}

std::unique_ptr<HalfSpace> make_half_space(const Grid& grid, Real modulus, int threads) {
  return grid.periodic ? make_periodic_half_space(grid, modulus, threads)
                       : make_nonperiodic_half_space(grid, modulus, threads);
}

}  // namespace contactbench
