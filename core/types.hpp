// Scalars, indices and the array types every module shares (docs/architecture.md: "one header").
#pragma once

#include <complex>
#include <cstddef>
#include <numbers>

#include <Eigen/Core>

namespace contactbench {

using Real = double;
using Index = std::ptrdiff_t;
using Complex = std::complex<Real>;

// pi as a Real, for the formulas of docs/theory.md (one definition: files that each defined their own clashed
// when compiled together, CMAKE_UNITY_BUILD).
inline constexpr Real pi = std::numbers::pi;

// Heights on an Nx x Ny grid, row-major with x fastest: rows are y, columns are x.
// heights(iy, ix) is the height at (x, y) = (ix * dx, iy * dy).
using HeightMap = Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Fourier coefficients on the half lattice of a real field (FFTW's r2c layout):
// ny rows (ky) by nx/2 + 1 columns (kx >= 0); the other half follows from Hermitian symmetry.
using SpectrumMap = Eigen::Array<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The thread policy, in one place: below this many points a loop runs on the calling thread alone (opening
// an OpenMP region costs tens of microseconds on these machines, more than the work, and oversubscribed
// spinning threads cost far more); from it on, on every thread asked for.
inline constexpr Index kMinPointsForThreads = Index{1} << 16;

// Whether work over `points` points is worth a parallel region.
constexpr bool worth_threads(Index points) {
  return points >= kMinPointsForThreads;
}

// The threads a loop over `points` points runs on, of `threads` asked for (at least one).
constexpr int team_size(Index points, int threads) {
  return worth_threads(points) && threads > 1 ? threads : 1;
}

}  // namespace contactbench
