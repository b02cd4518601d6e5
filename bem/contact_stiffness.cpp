#include "contactbench/bem/contact_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

using SpectrumMultiplier = Eigen::Array<Real, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct ContactStiffnessSolver::Impl {
  Impl(const Grid& grid_in, Real modulus, std::optional<Real> hardness, int threads,
       StiffnessOptions options_in)
      : grid(grid_in),
        options(options_in),
        // Plastic points (p at the cap H, to round-off) keep their pressure: only the elastic contact moves.
        cap(hardness ? *hardness * (1 - 1e-12) : std::numeric_limits<Real>::infinity()),
        operator_g(make_half_space(grid_in, modulus, threads)),
        fft(grid_in.nx, grid_in.ny, threads),
        inverse(grid_in.ny, fft.nx_half()) {
    // The preconditioner is P G^-1 P with the periodic inverse E* |q|/2 (the mean mode given that of the
    // smallest wavevector, to stay positive): the Fourier preconditioner of docs/solvers.md, which takes out
    // the 1/|q| spread of G's spectrum that makes plain CG slow on fine grids.
    const HalfLattice lattice(grid);
    const auto qx = lattice.qx_row();
    const auto qy = lattice.qy_column();
    const Real smallest = std::min(grid.dqx(), grid.dqy());
    for (Index row = 0; row < grid.ny; ++row)
      for (Index col = 0; col < fft.nx_half(); ++col)
        inverse(row, col) =
            modulus / 2 * std::max(std::hypot(qx(col), qy(row)), smallest) / static_cast<Real>(grid.points());
    complex_inverse = inverse.cast<Complex>();
  }

  void precondition(const HeightMap& residual, const HeightMap& mask, HeightMap& out) {
    fft.real() = residual * mask;
    fft.forward();
    fft.spectrum() *= complex_inverse;
    fft.backward();
    out = fft.real() * mask;
  }

  ContactStiffness solve(const HeightMap& pressure);

  Grid grid;
  StiffnessOptions options;
  Real cap;
  std::unique_ptr<HalfSpace> operator_g;
  RealFft2d fft;
  SpectrumMultiplier inverse;
  Eigen::Array<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> complex_inverse;
};

ContactStiffness ContactStiffnessSolver::Impl::solve(const HeightMap& pressure) {
  ContactStiffness result;
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
  // Preconditioned conjugate gradients on A = P G P (P: restriction to C), right-hand side b = 1 on C.
  HeightMap x = HeightMap::Zero(grid.ny, grid.nx);
  HeightMap r = mask;  // b - A x
  HeightMap z(grid.ny, grid.nx), a_d(grid.ny, grid.nx);
  precondition(r, mask, z);
  HeightMap d = z;
  const Real b_norm = std::sqrt(static_cast<Real>(on_set));
  Real rz = (r * z).sum(), rr = (r * r).sum();
  for (Index it = 0; it < options.max_iterations; ++it) {
    if (std::sqrt(rr) <= options.tolerance * b_norm) {
      result.converged = true;
      break;
    }
    operator_g->apply(d, a_d);
    a_d *= mask;
    const Real step = rz / (d * a_d).sum();
    x += step * d;
    r -= step * a_d;
    rr = (r * r).sum();
    precondition(r, mask, z);
    const Real rz_next = (r * z).sum();
    d = z + (rz_next / rz) * d;
    rz = rz_next;
    result.iterations = it + 1;
  }
  result.residual = std::sqrt(rr) / b_norm;
  if (!result.converged) result.converged = result.residual <= options.tolerance;
  // The energy estimate (header): b.x + x.r, whose error is quadratic in r (from x = 0, x.r vanishes in
  // exact arithmetic, r being orthogonal to the Krylov space x lies in; kept for the round-off).
  result.stiffness = (x.sum() + (x * r).sum()) / static_cast<Real>(points);
  return result;
}

ContactStiffnessSolver::ContactStiffnessSolver(const Grid& grid, Real modulus, std::optional<Real> hardness,
                                               int threads, StiffnessOptions options)
    : impl_(std::make_unique<Impl>(grid, modulus, hardness, threads, options)) {}

ContactStiffnessSolver::~ContactStiffnessSolver() = default;

ContactStiffness ContactStiffnessSolver::solve(const HeightMap& pressure) {
  return impl_->solve(pressure);
}

ContactStiffness contact_stiffness(const Grid& grid, Real modulus, const HeightMap& pressure,
                                   std::optional<Real> hardness, int threads, Real tolerance,
                                   Index max_iterations) {
  ContactStiffnessSolver solver(grid, modulus, hardness, threads,
                                {.tolerance = tolerance, .max_iterations = max_iterations});
  return solver.solve(pressure);
}

}  // namespace contactbench
