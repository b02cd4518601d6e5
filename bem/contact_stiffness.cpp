#include "contactbench/bem/contact_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

ContactStiffness contact_stiffness(const Grid& grid, Real modulus, const HeightMap& pressure,
                                   std::optional<Real> hardness, int threads, Real tolerance,
                                   Index max_iterations) {
  ContactStiffness result;
  // Plastic points (p at the cap H, to round-off) keep their pressure: only the elastic contact moves.
  const Real cap = hardness ? *hardness * (1 - 1e-12) : std::numeric_limits<Real>::infinity();
  const HeightMap mask = ((pressure > 0) && (pressure < cap)).cast<Real>();
  const auto on_set = static_cast<Index>(mask.sum());
  const Index points = grid.points();
  if (on_set == 0) {
    result.converged = true;
    return result;
  }
  if (grid.periodic && on_set == points) {
    // Full contact of a periodic surface: an approach needs an unbounded pressure.
    result.stiffness = std::numeric_limits<Real>::infinity();
    result.converged = true;
    return result;
  }
  std::unique_ptr<HalfSpace> operator_g = make_half_space(grid, modulus, threads);
  // Preconditioned conjugate gradients on A = P G P (P: restriction to C), right-hand side 1 on C, from
  // x = 0. The preconditioner is P G^-1 P with the periodic inverse E* |q|/2 (the mean mode given that of the
  // smallest wavevector, to stay positive): the Fourier preconditioner of docs/solvers.md, which takes out
  // the 1/|q| spread of G's spectrum that makes plain CG slow on fine grids.
  RealFft2d fft(grid.nx, grid.ny, threads);
  const HalfLattice lattice(grid);
  const auto qx = lattice.qx_row();
  const auto qy = lattice.qy_column();
  const Real smallest = std::min(grid.dqx(), grid.dqy());
  Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> inverse(grid.ny, fft.nx_half());
  for (Index row = 0; row < grid.ny; ++row)
    for (Index col = 0; col < fft.nx_half(); ++col)
      inverse(row, col) =
          modulus / 2 * std::max(std::hypot(qx(col), qy(row)), smallest) / static_cast<Real>(points);
  const auto precondition = [&](const HeightMap& residual, HeightMap& out) {
    fft.real() = residual * mask;
    fft.forward();
    fft.spectrum() *= inverse.cast<Complex>();
    fft.backward();
    out = fft.real() * mask;
  };
  HeightMap x = HeightMap::Zero(grid.ny, grid.nx);
  HeightMap r = mask;  // b - A x
  HeightMap z(grid.ny, grid.nx), a_d(grid.ny, grid.nx);
  precondition(r, z);
  HeightMap d = z;
  const Real b_norm = std::sqrt(static_cast<Real>(on_set));
  Real rz = (r * z).sum(), rr = (r * r).sum();
  for (Index it = 0; it < max_iterations; ++it) {
    if (std::sqrt(rr) <= tolerance * b_norm) {
      result.converged = true;
      break;
    }
    operator_g->apply(d, a_d);
    a_d *= mask;
    const Real step = rz / (d * a_d).sum();
    x += step * d;
    r -= step * a_d;
    rr = (r * r).sum();
    precondition(r, z);
    const Real rz_next = (r * z).sum();
    d = z + (rz_next / rz) * d;
    rz = rz_next;
    result.iterations = it + 1;
  }
  result.residual = std::sqrt(rr) / b_norm;
  if (!result.converged) result.converged = result.residual <= tolerance;
  result.stiffness = x.sum() / static_cast<Real>(points);
  return result;
}

}  // namespace contactbench
