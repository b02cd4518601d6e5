// The edge shares every non-periodic BEM run reports (bem/contact_statistics.hpp; docs/studies.md "Edges of
// non-periodic records"): a flat record pressed into full contact puts exactly the ring's share of the nodes
// in the ring, and more than that share of the load (the edge of a flat punch carries a singular pressure).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/contact_statistics.hpp"
#include "contactbench/core/labelling.hpp"

namespace contactbench {
namespace {

// Nearly flat: a wave of 1 nm on 100 um (a height range for the solver's residual), whose Westergaard
// pressure for full contact, pi E* (1 nm)/(100 um) = 3 MPa, is far below the 100 MPa pressed with.
Surface flat(Index n, bool periodic) {
  const Grid grid{.nx = n, .ny = n, .lx = 1e-4, .ly = 1e-4, .periodic = periodic};
  HeightMap h(n, n);
  for (Index iy = 0; iy < n; ++iy)
    for (Index ix = 0; ix < n; ++ix)
      h(iy, ix) = 1e-9 * std::cos(2 * std::numbers::pi * static_cast<Real>(ix) / static_cast<Real>(n));
  return Surface(grid, h);
}

TEST(EdgeShares, FlatRecordInFullContactIsAFlatPunch) {
  constexpr Index n = 64;
  BemSolver solver(flat(n, false), 1e11);
  const ContactSolution& solution = solver.solve(1e8);
  Labeller labeller(Topology::for_surface(Connectivity::four, false));
  const ContactStatistics s = contact_statistics(solution, labeller);
  ASSERT_EQ(solution.contact_points, n * n);
  // Every node in contact: the contact share is the ring's share of the nodes, 4 w (n - w)/n^2, exactly
  // (a ratio of integers; tolerance one rounding).
  const Real ring = 4.0 * kEdgeRingPixels * (n - kEdgeRingPixels) / (n * n);
  EXPECT_NEAR(s.edge_contact_share, ring, 1e-15);
  // The punch's pressure rises as 1/sqrt(distance to the edge): the ring carries more than its area's
  // share; require strictly more.
  EXPECT_GT(s.edge_load_share, ring);
  EXPECT_LE(s.edge_load_share, 1.0);
}

TEST(EdgeShares, PeriodicSolvesHaveNoEdge) {
  constexpr Index n = 64;
  BemSolver solver(flat(n, true), 1e11);
  const ContactSolution& solution = solver.solve(1e8);
  Labeller labeller(Topology::for_surface(Connectivity::four, true));
  const ContactStatistics s = contact_statistics(solution, labeller);
  EXPECT_EQ(s.edge_contact_share, 0);
  EXPECT_EQ(s.edge_load_share, 0);
}

}  // namespace
}  // namespace contactbench
