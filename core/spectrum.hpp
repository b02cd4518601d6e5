// Spectra and spectral moments of a surface (docs/theory.md section 1).
//
// Conventions, named in every output:
// - Fourier-series coefficients hhat_k = (1/(Nx Ny)) sum_x h(x) exp(-i q_k.x), q_k = 2 pi (kx/Lx, ky/Ly),
//   stored on the half lattice kx >= 0 (types.hpp); <h^2> = sum_k |hhat_k|^2 over the full lattice.
// - 2D PSD in Persson's convention: C(q_k) = |hhat_k|^2 / (dqx dqy), <h^2> = int d^2q C(q).
// - Moments are profile (Nayak) moments summed over the lattice: m_n along x = sum_k qx^n |hhat_k|^2.
// - The mean (k = 0) is excluded everywhere: moments describe the heights about their mean.
// - Non-periodic surfaces are windowed (Hann, separable, normalised to keep the mean square) before the
//   transform, because the jump at the edges of a non-periodic record would otherwise add a q^-2 tail that
//   inflates m2 and m4. Periodic surfaces are transformed as they are, which makes the moments exact.
#pragma once

#include <string_view>
#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

// Wavevectors of the stored half lattice of a grid.
class HalfLattice {
 public:
  explicit HalfLattice(const Grid& grid);

  Index rows() const { return ny_; }          // ky index, FFTW order: 0, 1, ..., then negatives
  Index cols() const { return nx_ / 2 + 1; }  // kx = 0 .. nx/2
  Index kx(Index col) const { return col; }
  Index ky(Index row) const { return row <= (ny_ - 1) / 2 ? row : row - ny_; }
  Real qx(Index col) const { return dqx_ * static_cast<Real>(kx(col)); }
  Real qy(Index row) const { return dqy_ * static_cast<Real>(ky(row)); }
  // The Nyquist column/row (even sizes only): the wavevector pi/dx that the lattice cannot tell from -pi/dx.
  bool nyquist_col(Index col) const { return nx_ % 2 == 0 && col == nx_ / 2; }
  bool nyquist_row(Index row) const { return ny_ % 2 == 0 && row == ny_ / 2; }
  // How many modes of the full lattice a stored coefficient stands for: itself and its conjugate -k,
  // except on kx = 0 and the Nyquist column, where -k is stored too.
  Real multiplicity(Index col) const { return (col == 0 || nyquist_col(col)) ? 1.0 : 2.0; }

  Eigen::Array<Real, 1, Eigen::Dynamic> qx_row() const;     // qx per column
  Eigen::Array<Real, Eigen::Dynamic, 1> qy_column() const;  // qy per row
  Eigen::Array<Real, 1, Eigen::Dynamic> multiplicity_row() const;

 private:
  Index nx_, ny_;
  Real dqx_, dqy_;
};

enum class Window { none, hann };
std::string_view to_string(Window window);
// Hann for non-periodic surfaces, none for periodic ones (see the file comment).
Window default_window(const Grid& grid);

struct FourierCoefficients {
  Grid grid;
  Window window = Window::none;
  SpectrumMap hhat;  // ny x (nx/2+1); hhat(0, 0) is zero (mean removed)
};

// The mean is removed, the window applied (normalised by sqrt(<w^2>)), then the forward FFT / (Nx Ny).
FourierCoefficients fourier_coefficients(const Surface& surface, Window window, int threads = 1);
FourierCoefficients fourier_coefficients(const Surface& surface, int threads = 1);  // default_window

// Profile moments along x and y [m0: m^2, m2: 1, m4: m^-2] and what follows from them.
struct SpectralMoments {
  Real m0 = 0;
  Real m2x = 0, m4x = 0;
  Real m2y = 0, m4y = 0;

  Real rms_height() const;    // sqrt(m0)
  Real rms_gradient() const;  // areal gbar = sqrt(<|grad h|^2>) = sqrt(m2x + m2y)
  Real alpha_x() const;       // Nayak's bandwidth m0 m4 / m2^2 from the x-profile moments
  Real alpha_y() const;
};

SpectralMoments spectral_moments(const FourierCoefficients& coefficients);
// The moments are sums of squared heights and slopes: a height range or lateral size outside 1e-100 to
// 1e100 m would overflow them or make them vanish (core/scales.hpp). Throws Error naming the quantity.
// spectral_moments(Surface) checks it first; callers that take the coefficients themselves call it.
void check_summable_heights(const Surface& surface);
SpectralMoments spectral_moments(const Surface& surface, int threads = 1);  // default_window

// 2D PSD C(q_k) on the half lattice [m^4] (Persson's convention, see the file comment).
Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> psd_2d(const FourierCoefficients& c);

// A PSD sampled at wavevectors q [1/m]. `modes` counts the lattice modes behind each value.
struct SampledPsd {
  std::vector<Real> q;
  std::vector<Real> c;
  std::vector<Index> modes;
};

// Radial average of the 2D PSD over log-spaced bins in |q| from the smallest to the largest lattice
// wavevector; q is the mean |q| of the modes in a bin and c the mean C; bins holding no mode are dropped.
SampledPsd radial_psd(const FourierCoefficients& coefficients, int bins_per_decade = 10);

// Profile PSDs (two-sided): C1x(qx) = sum_ky |hhat(kx, ky)|^2 / dqx, so that <h^2> = sum_kx C1x dqx and
// m2x = sum_kx qx^2 C1x dqx over kx in [-Nx/2, Nx/2). Listed for kx = 0 .. Nx/2; C1x(-qx) = C1x(qx).
SampledPsd profile_psd_x(const FourierCoefficients& coefficients);
SampledPsd profile_psd_y(const FourierCoefficients& coefficients);

}  // namespace contactbench
