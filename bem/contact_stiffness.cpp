#include "contactbench/bem/contact_stiffness.hpp"

#include <cmath>
#include <limits>
#include <memory>

#include "contactbench/bem/half_space.hpp"

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
  // Conjugate gradients on A = P G P (P: restriction to C), right-hand side 1 on C, from x = 0.
  HeightMap x = HeightMap::Zero(grid.ny, grid.nx);
  HeightMap r = mask;  // b - A x
  HeightMap d = r, a_d(grid.ny, grid.nx);
  const Real b_norm = std::sqrt(static_cast<Real>(on_set));
  Real rr = (r * r).sum();
  for (Index it = 0; it < max_iterations; ++it) {
    if (std::sqrt(rr) <= tolerance * b_norm) {
      result.converged = true;
      break;
    }
    operator_g->apply(d, a_d);
    a_d *= mask;
    const Real step = rr / (d * a_d).sum();
    x += step * d;
    r -= step * a_d;
    const Real rr_next = (r * r).sum();
    d = r + (rr_next / rr) * d;
    rr = rr_next;
    result.iterations = it + 1;
  }
  result.residual = std::sqrt(rr) / b_norm;
  if (!result.converged) result.converged = result.residual <= tolerance;
  result.stiffness = x.sum() / static_cast<Real>(points);
  return result;
}

}  // namespace contactbench
