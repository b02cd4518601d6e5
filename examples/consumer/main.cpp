// Generates the paper's surface A (docs/theory.md section 2) and solves one boundary-element load on it with
// the installed contactbench libraries; prints the contact area fraction and how the solve went.
#include <cstdlib>
#include <iostream>

#include <contactbench/bem/bem_solver.hpp>
#include <contactbench/core/generation.hpp>
#include <contactbench/core/material.hpp>

int main() {
  namespace cb = contactbench;
  const cb::Surface surface = cb::generate_surface(cb::paper::grid(), cb::paper::surface_a(), /*seed=*/3);
  const cb::Real modulus =
      cb::contact_modulus(100e9, 0.3);  // E* [Pa] of E = 100 GPa, nu = 0.3 on a rigid flat

  // P/(E* A0) = 1e-3: a few per cent of the surface in contact.
  cb::BemSolver solver(surface, modulus, {.tolerance = 1e-8});
  const cb::ContactSolution& solution = solver.solve(1e-3 * modulus);

  const double area_fraction = double(solution.contact_points) / double(surface.grid().points());
  std::cout << "surface A, " << surface.grid().nx << " x " << surface.grid().ny
            << " points, P/(E* A0) = 1e-3: A/A0 = " << area_fraction << " (nodes in contact), "
            << solution.iterations << " iterations, converged = " << std::boolalpha << solution.converged
            << '\n';
  // A sanity check a user would make: the solve converged to a contact of a few per cent.
  return solution.converged && area_fraction > 0.001 && area_fraction < 0.1 ? EXIT_SUCCESS : EXIT_FAILURE;
}
