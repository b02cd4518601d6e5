#include "contactbench/core/spectrum.hpp"

#include "contactbench/core/error.hpp"
#include "contactbench/core/scales.hpp"

#include <cmath>
#include <numbers>

#include "contactbench/core/fft.hpp"

namespace contactbench {

HalfLattice::HalfLattice(const Grid& grid) : nx_(grid.nx), ny_(grid.ny), dqx_(grid.dqx()), dqy_(grid.dqy()) {}

Eigen::Array<Real, 1, Eigen::Dynamic> HalfLattice::qx_row() const {
  return Eigen::Array<Real, 1, Eigen::Dynamic>::LinSpaced(cols(), 0, static_cast<Real>(cols() - 1)) * dqx_;
}

Eigen::Array<Real, Eigen::Dynamic, 1> HalfLattice::qy_column() const {
  Eigen::Array<Real, Eigen::Dynamic, 1> q(rows());
  for (Index row = 0; row < rows(); ++row)
    q(row) = qy(row);
  return q;
}

Eigen::Array<Real, 1, Eigen::Dynamic> HalfLattice::multiplicity_row() const {
  Eigen::Array<Real, 1, Eigen::Dynamic> m(cols());
  for (Index col = 0; col < cols(); ++col)
    m(col) = multiplicity(col);
  return m;
}

std::string_view to_string(Window window) {
  return window == Window::hann ? "hann" : "none";
}

Window default_window(const Grid& grid) {
  return grid.periodic ? Window::none : Window::hann;
}

namespace {

// Hann window sin^2(pi (i + 1/2) / n): symmetric about the record's centre and nowhere exactly zero.
Eigen::Array<Real, Eigen::Dynamic, 1> hann(Index n) {
  const Eigen::Array<Real, Eigen::Dynamic, 1> i =
      Eigen::Array<Real, Eigen::Dynamic, 1>::LinSpaced(n, 0.5, static_cast<Real>(n) - 0.5);
  return (std::numbers::pi * i / static_cast<Real>(n)).sin().square();
}

using PowerMap = Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

PowerMap power(const FourierCoefficients& c) {
  return c.hhat.abs2();
}

}  // namespace

FourierCoefficients fourier_coefficients(const Surface& surface, Window window, int threads) {
  const Grid& grid = surface.grid();
  RealFft2d& fft = cached_fft(grid.nx, grid.ny, threads);
  auto real = fft.real();
  real = surface.heights() - surface.mean_height();
  if (window == Window::hann) {
    const Eigen::Array<Real, Eigen::Dynamic, 1> wx = hann(grid.nx), wy = hann(grid.ny);
    // Normalise by the rms of the separable window so that the mean square of the heights is kept.
    const Real rms_window = std::sqrt(wx.square().mean() * wy.square().mean());
    real = (real.colwise() * wy).rowwise() * (wx / rms_window).transpose();
  }
  fft.forward();
  FourierCoefficients result{grid, window, fft.spectrum() / static_cast<Real>(grid.points())};
  result.hhat(0, 0) = 0;  // the mean: removed above, cleared of round-off here
  return result;
}

FourierCoefficients fourier_coefficients(const Surface& surface, int threads) {
  return fourier_coefficients(surface, default_window(surface.grid()), threads);
}

Real SpectralMoments::rms_height() const {
  return std::sqrt(m0);
}
Real SpectralMoments::rms_gradient() const {
  return std::sqrt(m2x + m2y);
}
Real SpectralMoments::alpha_x() const {
  return m0 * m4x / (m2x * m2x);
}
Real SpectralMoments::alpha_y() const {
  return m0 * m4y / (m2y * m2y);
}

SpectralMoments spectral_moments(const FourierCoefficients& c) {
  const HalfLattice lattice(c.grid);
  // Each stored |hhat_k|^2 weighted by the number of full-lattice modes it stands for.
  const PowerMap weighted = power(c).rowwise() * lattice.multiplicity_row();
  // Concrete arrays, not `auto`: an Eigen expression over a temporary would dangle.
  const Eigen::Array<Real, 1, Eigen::Dynamic> qx2 = lattice.qx_row().square();
  const Eigen::Array<Real, Eigen::Dynamic, 1> qy2 = lattice.qy_column().square();
  SpectralMoments m;
  m.m0 = weighted.sum();
  m.m2x = (weighted.rowwise() * qx2).sum();
  m.m4x = (weighted.rowwise() * qx2.square()).sum();
  m.m2y = (weighted.colwise() * qy2).sum();
  m.m4y = (weighted.colwise() * qy2.square()).sum();
  return m;
}

void check_summable_heights(const Surface& surface) {
  const HeightMap& h = surface.heights();
  const Real range = h.size() ? h.maxCoeff() - h.minCoeff() : 0;
  if (!within_magnitudes(range))
    throw Error("spectral moments: " + magnitude_problem("the heights' range", range, "m") +
                ": rescale the heights (e.g. to micrometres given in metres)");
  for (const Real size : {surface.grid().lx, surface.grid().ly})
    if (!within_magnitudes(size))
      throw Error("spectral moments: " + magnitude_problem("the lateral size", size, "m"));
}

SpectralMoments spectral_moments(const Surface& surface, int threads) {
  check_summable_heights(surface);
  return spectral_moments(fourier_coefficients(surface, threads));
}

PowerMap psd_2d(const FourierCoefficients& c) {
  return power(c) / (c.grid.dqx() * c.grid.dqy());
}

SampledPsd radial_psd(const FourierCoefficients& c, int bins_per_decade) {
  const HalfLattice lattice(c.grid);
  const PowerMap psd = psd_2d(c);
  const Eigen::Array<Real, 1, Eigen::Dynamic> qx = lattice.qx_row();
  const Eigen::Array<Real, Eigen::Dynamic, 1> qy = lattice.qy_column();
  const PowerMap q_abs = (qy.square().replicate(1, lattice.cols()).rowwise() + qx.square()).sqrt();

  const Real q_min = std::min(c.grid.dqx(), c.grid.dqy());
  const Real q_max = q_abs.maxCoeff();
  const int bins = std::max(2, static_cast<int>(std::ceil(bins_per_decade * std::log10(q_max / q_min))) + 1);
  const Real log_width = std::log(q_max / q_min) / (bins - 1);
  std::vector<Real> sum_q(bins, 0), sum_c(bins, 0), weight(bins, 0);
  std::vector<Index> modes(bins, 0);
  for (Index row = 0; row < lattice.rows(); ++row)
    for (Index col = 0; col < lattice.cols(); ++col) {
      if (row == 0 && col == 0) continue;  // the mean
      // Bin centres at q_min * exp(j log_width): round to the nearest in log q.
      const int bin = static_cast<int>(std::lround(std::log(q_abs(row, col) / q_min) / log_width));
      const Real m = lattice.multiplicity(col);
      sum_q[bin] += m * q_abs(row, col);
      sum_c[bin] += m * psd(row, col);
      weight[bin] += m;
      modes[bin] += static_cast<Index>(m);
    }
  SampledPsd result;
  for (int bin = 0; bin < bins; ++bin) {
    if (modes[bin] == 0) continue;
    result.q.push_back(sum_q[bin] / weight[bin]);
    result.c.push_back(sum_c[bin] / weight[bin]);
    result.modes.push_back(modes[bin]);
  }
  return result;
}

SampledPsd profile_psd_x(const FourierCoefficients& c) {
  const HalfLattice lattice(c.grid);
  // Summing a column over all ky is Parseval along y: the mean 1D periodogram of the rows.
  const Eigen::Array<Real, 1, Eigen::Dynamic> per_column = power(c).colwise().sum() / c.grid.dqx();
  SampledPsd result;
  for (Index col = 0; col < lattice.cols(); ++col) {
    result.q.push_back(lattice.qx(col));
    result.c.push_back(per_column(col));
    result.modes.push_back(lattice.rows());
  }
  return result;
}

SampledPsd profile_psd_y(const FourierCoefficients& c) {
  const HalfLattice lattice(c.grid);
  const PowerMap p = power(c);
  SampledPsd result;
  for (Index row = 0; row <= c.grid.ny / 2; ++row) {
    // Row ky holds the stored kx >= 0; the modes (-kx, ky) are the conjugates of (kx, -ky).
    const Index mirror = (c.grid.ny - row) % c.grid.ny;
    Real sum = 0;
    for (Index col = 0; col < lattice.cols(); ++col)
      sum += p(row, col) + (lattice.multiplicity(col) - 1) * p(mirror, col);
    result.q.push_back(std::abs(lattice.qy(row)));
    result.c.push_back(sum / c.grid.dqy());
    result.modes.push_back(c.grid.nx);
  }
  return result;
}

}  // namespace contactbench
