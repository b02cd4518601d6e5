// Hard cases of the boundary-element solvers with a checked answer, not only "no crash": grids of 1 x 1,
// 1 x N and 2 x 2, periodic and not, and problems at the ends of the magnitudes the library accepts
// (core/scales.hpp: 1e-100 to 1e100 of the SI unit), in double and single precision, against the scaled
// answer of a unit problem.
#include <gtest/gtest.h>

#include "contact_shapes.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/bem/love_kernel.hpp"
#include "contactbench/core/generation.hpp"
#include "each_solver.hpp"
#include "test_constants.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

class BemHardCases : public EachSolver {};

Surface flat(Index nx, Index ny, Real dx, bool periodic) {
  const Grid grid{.nx = nx, .ny = ny, .lx = nx * dx, .ly = ny * dx, .periodic = periodic};
  return Surface(grid, HeightMap::Zero(ny, nx));
}

// The displacement at node (ix, iy) of a pressure p on the nodes of a non-periodic grid, summed directly
// over Love's kernel (bem/love_kernel.hpp; no FFT, no padding): what the solver's operator must reproduce.
Real love_sum(const HeightMap& p, Index ix, Index iy, Real dx, Real dy) {
  Real u = 0;
  for (Index jy = 0; jy < p.rows(); ++jy)
    for (Index jx = 0; jx < p.cols(); ++jx)
      u += p(jy, jx) * love_displacement((ix - jx) * dx, (iy - jy) * dy, dx / 2, dy / 2);
  return u / testing::kPaperModulus;
}

TEST_P(BemHardCases, OnePixelIsLovesUniformlyLoadedRectangle) {
  // One non-periodic pixel in contact carries the load as a uniform pressure on its rectangle: the
  // approach is the displacement at the centre of a uniformly loaded rectangle (Love 1929; docs/theory.md
  // 7.6), for a square of side s: (4 ln(1 + sqrt2)/pi) p s/E* = 1.122200 p s/E*. (The uniformly loaded
  // square, not the rigid square punch, whose displacement is uniform and pressure is not: one pixel cannot
  // hold a pressure that varies.) Exact up to round-off: nothing iterates on one node.
  const Real pbar = 1e7;
  for (const Real aspect : {1.0, 2.0}) {
    const Grid grid{.nx = 1, .ny = 1, .lx = 1e-6 * aspect, .ly = 1e-6, .periodic = false};
    BemSolver solver(Surface(grid, HeightMap::Constant(1, 1, 3e-7)), testing::kPaperModulus,
                     {.solver = GetParam()});
    const ContactSolution& s = solver.solve(pbar);
    const std::string what = "aspect " + std::to_string(aspect);
    ASSERT_TRUE(s.converged) << what;
    EXPECT_EQ(s.contact_points, 1) << what;
    EXPECT_NEAR(s.pressure(0, 0), pbar, 1e-12 * pbar) << what;
    EXPECT_EQ(s.gap(0, 0), 0) << what;
    const Real approach = solver.surface().heights()(0, 0) - s.separation;
    const Real love = love_displacement(0, 0, grid.lx / 2, grid.ly / 2) * pbar / testing::kPaperModulus;
    EXPECT_NEAR(approach, love, 1e-12 * love) << what;
    if (aspect == 1.0) {
      EXPECT_NEAR(approach / (pbar * grid.lx / testing::kPaperModulus), 4 * std::log(1 + std::sqrt(2.0)) / pi,
                  1e-12);
      EXPECT_NEAR(approach / (pbar * grid.lx / testing::kPaperModulus), 1.122200,
                  5e-7);  // Love's printed value
    }
  }
  // Periodic, one node is a flat surface: full contact, the pressure the load, the periodic operator's mean
  // displacement zero, so the flat sits at the (centred) height, 0.
  const Grid grid{.nx = 1, .ny = 1, .lx = 1e-6, .ly = 1e-6, .periodic = true};
  BemSolver solver(Surface(grid, HeightMap::Constant(1, 1, 3e-7)), testing::kPaperModulus,
                   {.solver = GetParam()});
  const ContactSolution& s = solver.solve(pbar);
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.contact_points, 1);
  EXPECT_NEAR(s.pressure(0, 0), pbar, 1e-12 * pbar);
  EXPECT_EQ(s.separation, 0);
  EXPECT_EQ(s.gap(0, 0), 0);
}

TEST_P(BemHardCases, TwoByTwoAndOneByNAnswerWhatLovesSumSays) {
  // A flat non-periodic surface is a rigid punch of the grid's shape: the approach is uniform and the
  // pressure the one whose displacement is uniform. On 2 x 2 symmetry makes the four pressures equal, so the
  // approach is pbar/E* times the sum of Love's kernel at the four offsets. On 1 x N and N x 1 the pressure
  // rises towards the ends; the check is that Love's direct sum of the answer's pressure is the approach at
  // every node (the solver's FFT convolution, padding and rescaling against a plain sum).
  const Real dx = 1e-6, pbar = 1e7;
  struct Case {
    Index nx, ny;
  };
  for (const Case c : {Case{2, 2}, Case{1, 16}, Case{16, 1}, Case{1, 2}}) {
    const std::string what = std::to_string(c.nx) + " x " + std::to_string(c.ny);
    BemSolver solver(flat(c.nx, c.ny, dx, false), testing::kPaperModulus,
                     {.tolerance = 1e-12, .solver = GetParam()});
    const ContactSolution& s = solver.solve(pbar);
    ASSERT_TRUE(s.converged) << what;
    ASSERT_TRUE(s.pressure.allFinite() && std::isfinite(s.separation)) << what;
    EXPECT_EQ(s.contact_points, c.nx * c.ny) << what;
    EXPECT_NEAR(s.pressure.mean(), pbar, 1e-12 * pbar) << what;
    const Real approach = -s.separation;  // the centred heights are 0
    for (Index iy = 0; iy < c.ny; ++iy)
      for (Index ix = 0; ix < c.nx; ++ix) {
        EXPECT_NEAR(love_sum(s.pressure, ix, iy, dx, dx), approach, 1e-9 * approach) << what << " at " << ix;
      }
    if (c.nx == 2 && c.ny == 2) {
      EXPECT_LT((s.pressure - pbar).abs().maxCoeff(), 1e-9 * pbar);
      const auto love = [&](Real x, Real y) { return love_displacement(x, y, dx / 2, dx / 2); };
      EXPECT_NEAR(approach, pbar / testing::kPaperModulus * (love(0, 0) + 2 * love(dx, 0) + love(dx, dx)),
                  1e-9 * approach);
    } else {
      // Symmetric about the middle, and the ends carry more than the middle (a rigid punch's edges).
      const HeightMap line = c.ny == 1 ? HeightMap(s.pressure) : HeightMap(s.pressure.transpose());
      EXPECT_LT((line - line.reverse()).abs().maxCoeff(), 1e-9 * pbar) << what;
      if (line.size() > 2) {
        EXPECT_GT(line(0, 0), line(0, line.size() / 2)) << what;
      }
    }
  }
  // Periodic 2 x 2 with one node raised: at a small load the load is all on it, 4 pbar.
  const Grid grid{.nx = 2, .ny = 2, .lx = 2 * dx, .ly = 2 * dx, .periodic = true};
  HeightMap h = HeightMap::Zero(2, 2);
  h(1, 0) = 1e-8;
  BemSolver solver(Surface(grid, h), testing::kPaperModulus, {.tolerance = 1e-12, .solver = GetParam()});
  const ContactSolution& s = solver.solve(1e3);
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.contact_points, 1);
  EXPECT_NEAR(s.pressure(1, 0), 4e3, 1e-12 * 4e3);
}

TEST_P(BemHardCases, OneRowIsWestergaardsPlaneProblem) {
  // A periodic grid of one row (or one column) is the plane problem: h = D cos(2 pi x/lambda) on 1 x 256
  // must give the answer of 4 x 256 (rows identical) to solver consistency, and the peak of Westergaard's
  // pressure 2 sqrt(pbar p*), p* = pi E* D/lambda, to 1e-3 (measured below 1e-4 on 256 points).
  const Index n = 256;
  const Real lambda = 100e-6, amplitude = 1e-6, p_star = pi * testing::kPaperModulus * amplitude / lambda;
  const auto strip = [&](Index rows, bool along_y) { return wavy(n, rows, along_y, lambda, amplitude); };
  const Real pbar = 0.3 * p_star;
  BemSolver wide(strip(4, false), testing::kPaperModulus, {.tolerance = 1e-12, .solver = GetParam()});
  BemSolver row(strip(1, false), testing::kPaperModulus, {.tolerance = 1e-12, .solver = GetParam()});
  BemSolver column(strip(1, true), testing::kPaperModulus, {.tolerance = 1e-12, .solver = GetParam()});
  const ContactSolution& w = wide.solve(pbar);
  const ContactSolution& r = row.solve(pbar);
  const ContactSolution& c = column.solve(pbar);
  ASSERT_TRUE(w.converged && r.converged && c.converged);
  EXPECT_LT((r.pressure.row(0) - w.pressure.row(1)).abs().maxCoeff(),
            tolerance::solver_consistency * w.pressure.maxCoeff());
  EXPECT_LT((c.pressure.col(0).transpose() - w.pressure.row(1)).abs().maxCoeff(),
            tolerance::solver_consistency * w.pressure.maxCoeff());
  EXPECT_EQ(4 * r.contact_points, w.contact_points);
  EXPECT_NEAR(r.pressure.maxCoeff(), 2 * std::sqrt(pbar * p_star), 1e-3 * 2 * std::sqrt(pbar * p_star));
}

// Surface A of the paper on 32 x 32 periodic points (or not), with its heights scaled to a range of 1 m and
// its sides to 1 m: the unit problem; and the same scaled by `height` and `lateral`.
Surface unit_problem(bool periodic, Real height, Real lateral) {
  const Grid grid{.nx = 32, .ny = 32, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  const Surface a = generate_surface(grid, paper::surface_a(), 7);
  const HeightMap& h = a.heights();
  const Grid scaled{.nx = 32, .ny = 32, .lx = lateral, .ly = lateral, .periodic = periodic};
  return Surface(scaled, (h - h.mean()) / (h.maxCoeff() - h.minCoeff()) * height);
}

// Linear elasticity has no length scale: heights scaled by sh and sides by sl scale the pressure at a given
// contact set by sh/sl, and the flat's height by sh. So a problem at the ends of what the library accepts
// (heights of 1e-99 m, sides of 1e-90 or 1e90 m, heights of 1e90 m; core/scales.hpp) must give the unit
// problem's answer scaled: the same contact set, the pressure / (sh/sl) and separation / sh equal to the
// unit ones. Load: 1 % of E* times the unit problem's height range per pixel (about 20 % contact), the mean
// pressure within the accepted range in every case.
struct Scale {
  Real height, lateral;
};
constexpr Scale kExtremeScales[] = {{1e-99, 1}, {1e-99, 1e-90}, {1, 1e90}, {1e90, 1e90}, {1e-9, 1e-90}};

// Runs one scaled problem against the unit one in the same precision; the failures, empty when it agrees.
// Double: to solver consistency (the scaled iterates differ by round-off only; measured at most 3.4e-12 of
// the peak). Single (tolerance 1e-6): float resolves about 1e-7 and its iterations stop at a relative change
// of 1e-6, so to 1e-4 of the peak and a node or two at the contact's edge.
std::string scaled_answer_problems(SolverKind kind, bool periodic, bool single, Scale scale,
                                   Real load_error = 1) {
  const BemSolverOptions options{.tolerance = single ? 1e-6 : 1e-12,
                                 .max_iterations = 20000,
                                 .single_precision = single,
                                 .solver = kind};
  BemSolver unit_solver(unit_problem(periodic, 1, 1), testing::kPaperModulus, options);
  const Real load = 0.01 * testing::kPaperModulus * 32;
  const ContactSolution reference = unit_solver.solve(load);
  const Real pressure_scale = scale.height / scale.lateral;
  std::ostringstream out;
  ContactSolution s;
  try {
    BemSolver solver(unit_problem(periodic, scale.height, scale.lateral), testing::kPaperModulus, options);
    s = solver.solve(load * pressure_scale * load_error);
  } catch (const std::exception& e) {
    return std::string("threw: ") + e.what();
  }
  if (!reference.converged) out << "the unit problem did not converge; ";
  if (!s.converged) out << "not converged (" << s.iterations << " iterations); ";
  if (!(s.pressure.allFinite() && std::isfinite(s.separation))) out << "not finite; ";
  const Real peak = reference.pressure.maxCoeff();
  const Real difference = (s.pressure / pressure_scale - reference.pressure).abs().maxCoeff() / peak;
  const Real separation = std::abs(s.separation / scale.height - reference.separation);
  const Index nodes = std::abs(s.contact_points - reference.contact_points);
  if (!(nodes <= (single ? 2 : 0)))
    out << s.contact_points << " contact nodes, not " << reference.contact_points << "; ";
  if (!(difference <= (single ? 1e-4 : tolerance::solver_consistency)))
    out << "pressure off by " << difference << " of the peak; ";
  if (!(separation <= (single ? 1e-4 : 1e-9))) out << "separation off by " << separation << " m (unit); ";
  return out.str();
}

// Not solved on this commit: active_set in double at heights of 1e-99 m on sides of 1e-90 m (20000
// iterations, no contact); it is marked not converged, never passed off as an answer (the test after next).
// Single precision at every extreme scale is refused before any work (float holds 1e-38 to 3e38: heights of
// 1e-99 m became 0 and the solve reported "converged" with no contact; sides of 1e90 m overflowed).
bool known_wrong(SolverKind kind, bool single, Scale scale) {
  return single || (kind == SolverKind::active_set && scale.height == 1e-99 && scale.lateral == 1e-90);
}

TEST_P(BemHardCases, ExtremeScalesGiveTheScaledAnswerOfAUnitProblem) {
  for (const bool periodic : {true, false})
    for (const bool single : {false, true})
      for (const Scale scale : kExtremeScales) {
        if (known_wrong(GetParam(), single, scale)) continue;
        EXPECT_EQ(scaled_answer_problems(GetParam(), periodic, single, scale), "")
            << (periodic ? "periodic" : "non-periodic") << (single ? ", float" : ", double") << ", heights x "
            << scale.height << ", sides x " << scale.lateral;
      }
}

// Where the scaled answer is not reached, it is not passed off: single precision is refused naming the
// quantity float cannot hold; active_set's case above ends marked not converged.
TEST_P(BemHardCases, ExtremeScalesOutOfReachAreRefusedOrMarked) {
  for (const bool periodic : {true, false})
    for (const bool single : {false, true})
      for (const Scale scale : kExtremeScales) {
        if (!known_wrong(GetParam(), single, scale)) continue;
        const std::string problems = scaled_answer_problems(GetParam(), periodic, single, scale);
        const std::string expected = single ? "single precision cannot hold" : "not converged";
        EXPECT_NE(problems.find(expected), std::string::npos)
            << problems << (periodic ? " periodic" : " non-periodic") << (single ? ", float" : ", double")
            << ", heights x " << scale.height << ", sides x " << scale.lateral;
      }
}

// The same check can fail: the scaled problem solved at a load 1e-6 off is rejected (its pressure moves by
// about 1e-6 of the peak, far above solver consistency).
TEST(BemHardCasesControls, TheScaledAnswerCheckRejectsALoadOffBy1e6) {
  for (const bool periodic : {true, false}) {
    EXPECT_EQ(scaled_answer_problems(SolverKind::polonsky_keer, periodic, false, {1e-99, 1e-90}), "");
    EXPECT_NE(scaled_answer_problems(SolverKind::polonsky_keer, periodic, false, {1e-99, 1e-90}, 1 + 1e-6),
              "");
  }
}

CB_FOR_EACH_SOLVER(BemHardCases);

}  // namespace
}  // namespace contactbench
