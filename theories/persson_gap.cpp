#include "contactbench/theories/persson_gap.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// F(s0) = int_s0^inf (1/s) [gamma + 3 (1 - gamma) erf^2(s)] exp(-s^2) ds, tabulated in t = ln s on
// [ln 1e-12, ln 8] (beyond 8, exp(-64) leaves nothing) by Simpson's rule from the top, and below 1e-12
// continued by its logarithmic head gamma ln(1e-12/s0) (erf^2 ~ s^2 is negligible there).
class InnerIntegral {
 public:
  explicit InnerIntegral(Real gamma) : gamma_(gamma) {
    const auto f = [&](Real t) {
      const Real s = std::exp(t), e = std::erf(s);
      return (gamma + 3 * (1 - gamma) * e * e) * std::exp(-s * s);
    };
    table_.assign(kNodes, 0);
    for (Index i = kNodes - 2; i >= 0; --i) {
      const Real a = t_at(i), b = t_at(i + 1);
      table_[static_cast<std::size_t>(i)] =
          table_[static_cast<std::size_t>(i + 1)] + (b - a) / 6 * (f(a) + 4 * f((a + b) / 2) + f(b));
    }
  }

  Real operator()(Real s0) const {
    const Real t = std::log(s0);
    if (t >= kTop) return 0;
    if (t <= kBottom) return table_.front() + gamma_ * (kBottom - t);
    const Real x = (t - kBottom) / step();
    const auto i = std::min(static_cast<Index>(x), kNodes - 2);
    const Real f = x - static_cast<Real>(i);
    return (1 - f) * table_[static_cast<std::size_t>(i)] + f * table_[static_cast<std::size_t>(i + 1)];
  }

 private:
  static constexpr Index kNodes = 40001;  // step 7.4e-4 in ln s: linear interpolation to ~1e-7 relative
  static constexpr Real kBottom = -27.631021115928547;  // ln 1e-12
  static constexpr Real kTop = 2.0794415416798357;      // ln 8
  static Real step() { return (kTop - kBottom) / static_cast<Real>(kNodes - 1); }
  static Real t_at(Index i) { return kBottom + static_cast<Real>(i) * step(); }
  Real gamma_;
  std::vector<Real> table_;
};

const InnerIntegral& inner_integral(Real gamma) {
  // One table per gamma used (in practice one): built in about a millisecond.
  static thread_local std::vector<std::pair<Real, InnerIntegral>> tables;
  for (const auto& [g, table] : tables)
    if (g == gamma) return table;
  tables.emplace_back(gamma, InnerIntegral(gamma));
  return tables.back().second;
}

}  // namespace

PerssonGap::PerssonGap(const FourierCoefficients& c, Real gamma) : gamma_(gamma) {
  if (!(gamma >= 0 && gamma <= 1)) throw Error("Persson's gap: gamma must lie in [0, 1]");
  const HalfLattice lattice(c.grid);
  const auto psd = psd_2d(c);
  const Real cell = c.grid.dqx() * c.grid.dqy();
  struct Mode {
    Real q, c_cell;  // |q|, C(q) dqx dqy times the modes it stands for
    Index row, col;
  };
  std::vector<Mode> modes;
  for (Index row = 0; row < lattice.rows(); ++row)
    for (Index col = 0; col < lattice.cols(); ++col) {
      const Real q = std::hypot(lattice.qx(col), lattice.qy(row));
      if (q > 0 && psd(row, col) > 0)
        modes.push_back({q, lattice.multiplicity(col) * psd(row, col) * cell, row, col});
    }
  if (modes.empty()) throw Error("Persson's gap: the surface has no roughness (every Fourier mode is 0)");
  // A total order (|q|, then the lattice position), so that the sums' order does not depend on the sort's
  // handling of ties.
  std::sort(modes.begin(), modes.end(), [](const Mode& a, const Mode& b) {
    return a.q != b.q ? a.q < b.q : a.row != b.row ? a.row < b.row : a.col < b.col;
  });
  // w(q) at a mode is the q^3 integral up to and including its whole shell |q'| = |q|: the modes of one
  // shell (+-ky, kx <-> ky on a square lattice, equal to round-off) share it. Cumulating mode by mode instead
  // gave the first modes of a shell different w by the order of equal |q|, which moved the mean gap by 0.8 %
  // on a 64^2 surface when round-off-sized modes (psd ~1e-57 of the empty Nyquist modes) came and went
  // (docs/theory.md section 12.3, docs/mpi.md).
  constexpr Real kShell = 1e-12;  // relative: |q| of one shell computed by different sums of squares
  Real q3 = 0;  // int_q0^q q'^3 C dq' = (1/(2 pi)) sum |q|^2 C dqx dqy over the modes up to q
  w_.reserve(modes.size());
  for (std::size_t first = 0; first < modes.size();) {
    std::size_t end = first;
    for (; end < modes.size() && modes[end].q <= modes[first].q * (1 + kShell); ++end) {
      const Mode& m = modes[end];
      q3 += m.q * m.q * m.c_cell / (2 * pi);
      weight_.push_back(m.q * m.c_cell / (2 * pi));
    }
    w_.insert(w_.end(), end - first, 1 / std::sqrt(pi * q3));
    first = end;
  }
}

Real PerssonGap::mean_gap(Real load) const {
  const InnerIntegral& inner = inner_integral(gamma_);
  Real sum = 0;
  for (std::size_t k = 0; k < w_.size(); ++k)
    sum += weight_[k] * w_[k] * inner(w_[k] * load);
  return std::sqrt(pi) * sum;
}

Real PerssonGap::stiffness(Real load) const {
  Real sum = 0;  // -du-bar/d(load) load
  for (std::size_t k = 0; k < w_.size(); ++k) {
    const Real s = w_[k] * load, e = std::erf(s);
    sum += weight_[k] * w_[k] * (gamma_ + 3 * (1 - gamma_) * e * e) * std::exp(-s * s);
  }
  return load / (std::sqrt(pi) * sum);
}

Real persson_pressure_density(Real s, Real load, Real q3_integral) {
  const Real g = pi / 4 * q3_integral;
  if (s < 0) return 0;
  return (std::exp(-(s - load) * (s - load) / (4 * g)) - std::exp(-(s + load) * (s + load) / (4 * g))) /
         std::sqrt(4 * pi * g);
}

}  // namespace contactbench
