// Scalars, indices and the array types every module shares (docs/architecture.md: "one header").
#pragma once

#include <complex>
#include <cstddef>

#include <Eigen/Core>

namespace contactbench {

using Real = double;
using Index = std::ptrdiff_t;
using Complex = std::complex<Real>;

// Heights on an Nx x Ny grid, row-major with x fastest: rows are y, columns are x.
// heights(iy, ix) is the height at (x, y) = (ix * dx, iy * dy).
using HeightMap = Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Fourier coefficients on the half lattice of a real field (FFTW's r2c layout):
// ny rows (ky) by nx/2 + 1 columns (kx >= 0); the other half follows from Hermitian symmetry.
using SpectrumMap = Eigen::Array<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Below this many points a loop runs on the calling thread alone: opening an OpenMP region costs tens of
// microseconds on these machines, more than the work, and oversubscribed spinning threads cost far more.
inline constexpr Index kMinPointsForThreads = Index{1} << 16;

}  // namespace contactbench
