// A second, deliberately plain boundary-element solver for the negative controls of the analytic validations
// (tests/test_bem_solver.cpp): Polonsky & Keer's constrained conjugate gradient (Wear 231, 206-219, 1999),
// load control, written out on whole arrays against any operator u = G p. The library's solvers keep their
// kernel inside; this one takes the operator as an argument, so a test can hand it a wrong one (the kernel
// shifted by one node) and show that the validation's check then fails. With the right operator it must
// pass the same check (the tests assert that too), so a failure is the kernel's, not this solver's.
#pragma once

#include <cmath>
#include <functional>
#include <memory>

#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench::testing {

using Operator = std::function<void(const HeightMap& pressure, HeightMap& displacement)>;

struct PlainSolution {
  HeightMap pressure;   // [Pa]
  Real separation = 0;  // the flat's height d, gap = d - h + u [m]
  Index iterations = 0;
  bool converged = false;
};

// Solves for the mean pressure pbar on heights h (higher touches first): p >= 0, gap = d - h + G p >= 0,
// p gap = 0, mean p = pbar. Stops at a relative change sum |p - p_old| / sum p below tolerance.
inline PlainSolution plain_polonsky_keer(const HeightMap& h, Real pbar, const Operator& apply, Real tolerance,
                                         Index max_iterations) {
  const Index rows = h.rows(), cols = h.cols();
  const Real total = pbar * static_cast<Real>(h.size());
  PlainSolution s;
  s.pressure = HeightMap::Constant(rows, cols, pbar);
  HeightMap& p = s.pressure;
  HeightMap t = HeightMap::Zero(rows, cols), u, r;
  Real g_old = 1;
  bool conjugate = false;
  for (s.iterations = 1; s.iterations <= max_iterations; ++s.iterations) {
    apply(p, u);
    const auto in_contact = p > 0;
    const Real count = static_cast<Real>(in_contact.count());
    HeightMap g = u - h;
    g -= in_contact.select(g, 0.0).sum() / count;
    const Real g_norm = in_contact.select(g * g, 0.0).sum();
    t = in_contact.select(g + (conjugate ? g_norm / g_old : 0.0) * t, 0.0);
    g_old = g_norm;
    apply(t, r);
    r -= in_contact.select(r, 0.0).sum() / count;
    const Real tau = in_contact.select(g * t, 0.0).sum() / in_contact.select(r * t, 0.0).sum();
    const HeightMap old = p;
    p = (p - tau * t).max(0.0);
    // Nodes out of contact that the flat penetrates enter the set, and the conjugation restarts.
    const auto overlap = (p <= 0) && (g < 0);
    conjugate = overlap.count() == 0;
    p = overlap.select(-tau * g, p);
    p *= total / p.sum();
    if ((p - old).abs().sum() / p.sum() < tolerance) {
      s.converged = true;
      break;
    }
  }
  apply(p, u);
  const auto in_contact = p > 0;
  s.separation = in_contact.select(h - u, 0.0).sum() / static_cast<Real>(in_contact.count());
  return s;
}

// A field moved one node along x (x -> x + dx), wrapping when periodic, the vacated column zero when not.
inline HeightMap moved_one_node(const HeightMap& p, bool periodic) {
  HeightMap moved(p.rows(), p.cols());
  const Index n = p.cols();
  moved.rightCols(n - 1) = p.leftCols(n - 1);
  if (periodic)
    moved.col(0) = p.col(n - 1);
  else
    moved.col(0).setZero();
  return moved;
}

// The operator of a grid (bem/half_space.hpp), or the same with its kernel shifted by one node along x:
// u(x) = sum_y G(x - y - dx) p(y), the displacement registered one node off the pressure that causes it. The
// shifted operator is no longer symmetric, so a conjugate-gradient iteration on it need not settle.
inline Operator half_space_operator(const Grid& grid, Real modulus, bool shifted) {
  std::shared_ptr<HalfSpace> half_space = make_half_space(grid, modulus);
  if (!shifted) return [half_space](const HeightMap& p, HeightMap& u) { half_space->apply(p, u); };
  return [half_space, periodic = grid.periodic](const HeightMap& p, HeightMap& u) {
    half_space->apply(moved_one_node(p, periodic), u);
  };
}

}  // namespace contactbench::testing
