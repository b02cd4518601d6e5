#include "contactbench/core/formats/harmonic_fill.hpp"

#include <array>
#include <cmath>
#include <string>

#include <Eigen/Sparse>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// Below this many unknowns a level is solved directly (a sparse Cholesky factorisation: milliseconds).
constexpr Index kDirectSolveUnknowns = 4096;
// The coarse correction is scaled up: piecewise-constant aggregates make the coarse operator too stiff for
// smooth errors (a known trait of unsmoothed aggregation); 1.5 roughly halved the iterations on a half-plane
// hole (docs/formats.md "The harmonic fill's solver") while the cycle stays a symmetric positive definite
// preconditioner (the factor is below 2).
constexpr Real kCoarseCorrectionScale = 1.5;
constexpr Index kMaxIterations = 500;

// One level: its unknowns and the weighted five-point operator among them,
// (A x)_i = diagonal_i x_i - sum_k weight_ik x_(neighbour_ik). On the finest level the unknowns are the
// invalid points, the weights 1 and the diagonal the number of in-grid neighbours (the valid ones move to the
// right-hand side); each coarser level aggregates 2 x 2 cells of the one below, with the Galerkin operator
// P^T A P of the piecewise-constant prolongation P: the weight between two aggregates is the sum of the fine
// links between them, and links inside an aggregate cancel out of its diagonal. That is the same five-point
// form on every level, and it keeps the holes' shapes exactly, however thin.
struct FillLevel {
  Index nx = 0, ny = 0;
  std::vector<Index> cell;  // the grid cell (y nx + x) of each unknown
  std::vector<Real> diagonal;
  std::vector<std::array<Index, 4>> neighbour;  // left, right, up, down; -1: no unknown there
  std::vector<std::array<Real, 4>> weight;
  std::vector<Index> aggregate;  // the unknown of the next coarser level that each unknown belongs to
  // Work vectors of the cycle.
  std::vector<Real> residual, coarse_right, coarse_solution;

  Index size() const { return static_cast<Index>(diagonal.size()); }

  void resize(Index unknowns) {
    const auto n = static_cast<std::size_t>(unknowns);
    diagonal.assign(n, 0);
    neighbour.assign(n, {-1, -1, -1, -1});
    weight.assign(n, {0, 0, 0, 0});
  }

  Real row_times(Index i, const std::vector<Real>& x) const {
    const auto k = static_cast<std::size_t>(i);
    Real off = 0;
    for (int side = 0; side < 4; ++side)
      if (neighbour[k][side] >= 0) off += weight[k][side] * x[static_cast<std::size_t>(neighbour[k][side])];
    return diagonal[k] * x[k] - off;
  }

  void multiply(const std::vector<Real>& x, std::vector<Real>& y) const {
    for (Index i = 0; i < size(); ++i)
      y[static_cast<std::size_t>(i)] = row_times(i, x);
  }

  // One Gauss–Seidel sweep, forward before the coarse correction and backward after it, so that the cycle
  // is symmetric (the conjugate gradient needs a symmetric preconditioner).
  void gauss_seidel(std::vector<Real>& x, const std::vector<Real>& b, bool forward) const {
    for (Index step = 0; step < size(); ++step) {
      const auto i = static_cast<std::size_t>(forward ? step : size() - 1 - step);
      Real sum = b[i];
      for (int side = 0; side < 4; ++side)
        if (neighbour[i][side] >= 0) sum += weight[i][side] * x[static_cast<std::size_t>(neighbour[i][side])];
      x[i] = sum / diagonal[i];
    }
  }
};

// The finest level and its right-hand side: the valid neighbours' heights.
FillLevel finest_level(const std::vector<Real>& values, Index nx, Index ny, std::vector<Real>& right) {
  FillLevel level;
  level.nx = nx;
  level.ny = ny;
  std::vector<Index> unknown_of(values.size(), -1);
  for (std::size_t k = 0; k < values.size(); ++k)
    if (std::isnan(values[k])) {
      unknown_of[k] = static_cast<Index>(level.cell.size());
      level.cell.push_back(static_cast<Index>(k));
    }
  level.resize(static_cast<Index>(level.cell.size()));
  right.assign(level.cell.size(), 0);
  for (Index i = 0; i < level.size(); ++i) {
    const auto u = static_cast<std::size_t>(i);
    const Index k = level.cell[u], x = k % nx, y = k / nx;
    const std::array<Index, 4> sides{x > 0 ? k - 1 : -1, x + 1 < nx ? k + 1 : -1, y > 0 ? k - nx : -1,
                                     y + 1 < ny ? k + nx : -1};
    for (int side = 0; side < 4; ++side) {
      if (sides[side] < 0) continue;
      level.diagonal[u] += 1;
      const auto q = static_cast<std::size_t>(sides[side]);
      if (unknown_of[q] >= 0) {
        level.neighbour[u][side] = unknown_of[q];
        level.weight[u][side] = 1;
      } else {
        right[u] += values[q];
      }
    }
  }
  return level;
}

// The next coarser level: the 2 x 2 aggregates of `fine`'s cells that hold an unknown (sets fine.aggregate).
FillLevel coarser_level(FillLevel& fine) {
  FillLevel coarse;
  coarse.nx = (fine.nx + 1) / 2;
  coarse.ny = (fine.ny + 1) / 2;
  std::vector<Index> unknown_of(static_cast<std::size_t>(coarse.nx * coarse.ny), -1);
  fine.aggregate.resize(fine.cell.size());
  for (std::size_t i = 0; i < fine.cell.size(); ++i) {
    const Index k = fine.cell[i];
    const auto c = static_cast<std::size_t>((k / fine.nx / 2) * coarse.nx + (k % fine.nx) / 2);
    if (unknown_of[c] < 0) unknown_of[c] = 0;  // marked; numbered in cell order below
  }
  for (std::size_t c = 0; c < unknown_of.size(); ++c)
    if (unknown_of[c] >= 0) {
      unknown_of[c] = static_cast<Index>(coarse.cell.size());
      coarse.cell.push_back(static_cast<Index>(c));
    }
  coarse.resize(static_cast<Index>(coarse.cell.size()));
  for (std::size_t i = 0; i < fine.cell.size(); ++i) {
    const Index k = fine.cell[i];
    fine.aggregate[i] =
        unknown_of[static_cast<std::size_t>((k / fine.nx / 2) * coarse.nx + (k % fine.nx) / 2)];
  }
  for (std::size_t i = 0; i < fine.cell.size(); ++i) {
    const auto a = static_cast<std::size_t>(fine.aggregate[i]);
    coarse.diagonal[a] += fine.diagonal[i];
    for (int side = 0; side < 4; ++side) {
      const Index j = fine.neighbour[i][side];
      if (j < 0) continue;
      const Index b = fine.aggregate[static_cast<std::size_t>(j)];
      if (b == static_cast<Index>(a)) {
        coarse.diagonal[a] -= fine.weight[i][side];  // a link inside the aggregate: its two terms cancel
      } else {
        coarse.neighbour[a][side] = b;
        coarse.weight[a][side] += fine.weight[i][side];
      }
    }
  }
  return coarse;
}

Eigen::SparseMatrix<Real> sparse_matrix(const FillLevel& level) {
  std::vector<Eigen::Triplet<Real>> entries;
  entries.reserve(static_cast<std::size_t>(5 * level.size()));
  for (Index i = 0; i < level.size(); ++i) {
    const auto u = static_cast<std::size_t>(i);
    entries.emplace_back(i, i, level.diagonal[u]);
    for (int side = 0; side < 4; ++side)
      if (level.neighbour[u][side] >= 0)
        entries.emplace_back(i, level.neighbour[u][side], -level.weight[u][side]);
  }
  Eigen::SparseMatrix<Real> matrix(level.size(), level.size());
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

class FillMultigrid {
 public:
  explicit FillMultigrid(FillLevel finest) {
    levels_.push_back(std::move(finest));
    while (levels_.back().size() > kDirectSolveUnknowns) {
      FillLevel coarse = coarser_level(levels_.back());
      levels_.push_back(std::move(coarse));
    }
    for (FillLevel& level : levels_) {
      level.residual.resize(level.cell.size());
      level.coarse_right.resize(level.cell.size());
      level.coarse_solution.resize(level.cell.size());
    }
    direct_.compute(sparse_matrix(levels_.back()));
    if (direct_.info() != Eigen::Success)
      throw Error("harmonic fill: the coarsest Laplace system could not be factorised");
  }

  const FillLevel& finest() const { return levels_.front(); }
  Index levels() const { return static_cast<Index>(levels_.size()); }

  // x = B b, B the cycle's approximation of A^-1 (exact when there is one level).
  void cycle(std::vector<Real>& x, const std::vector<Real>& b) { cycle_at(0, x, b); }

 private:
  void cycle_at(std::size_t depth, std::vector<Real>& x, const std::vector<Real>& b) {
    FillLevel& level = levels_[depth];
    if (depth + 1 == levels_.size()) {
      const Eigen::Map<const Eigen::VectorXd> right(b.data(), level.size());
      Eigen::Map<Eigen::VectorXd>(x.data(), level.size()) = direct_.solve(right);
      return;
    }
    FillLevel& coarse = levels_[depth + 1];
    std::fill(x.begin(), x.end(), Real{0});
    level.gauss_seidel(x, b, true);
    level.multiply(x, level.residual);
    std::vector<Real>& coarse_right = coarse.coarse_right;
    std::vector<Real>& coarse_solution = coarse.coarse_solution;
    std::fill(coarse_right.begin(), coarse_right.end(), Real{0});
    for (std::size_t i = 0; i < x.size(); ++i)
      coarse_right[static_cast<std::size_t>(level.aggregate[i])] += b[i] - level.residual[i];  // P^T r
    cycle_at(depth + 1, coarse_solution, coarse_right);
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] += kCoarseCorrectionScale * coarse_solution[static_cast<std::size_t>(level.aggregate[i])];
    level.gauss_seidel(x, b, false);
  }

  std::vector<FillLevel> levels_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<Real>> direct_;
};

Real dot(const std::vector<Real>& a, const std::vector<Real>& b) {
  Real sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    sum += a[i] * b[i];
  return sum;
}

}  // namespace

HarmonicFillReport fill_harmonic(std::vector<Real>& values, Index nx, Index ny) {
  std::vector<Real> right;
  FillMultigrid multigrid(finest_level(values, nx, ny, right));
  const FillLevel& finest = multigrid.finest();
  HarmonicFillReport report{.unknowns = finest.size(), .levels = multigrid.levels()};
  if (finest.size() == 0) return report;

  // The preconditioned conjugate gradient from h = 0 (the classic form: Saad, Iterative Methods for Sparse
  // Linear Systems, algorithm 9.1).
  const auto n = static_cast<std::size_t>(finest.size());
  std::vector<Real> h(n, 0), r = right, z(n), p(n), q(n);
  const Real right_norm = std::sqrt(dot(right, right));
  multigrid.cycle(z, r);
  p = z;
  Real rz = dot(r, z);
  Real residual_norm = right_norm;
  while (right_norm > 0 && residual_norm > kHarmonicFillTolerance * right_norm) {
    if (report.iterations == kMaxIterations || !(rz > 0))
      throw Error("harmonic fill of " + std::to_string(finest.size()) + " invalid points did not converge: " +
                  "relative residual " + std::to_string(residual_norm / right_norm) + " after " +
                  std::to_string(report.iterations) + " iterations; fill with the mean (--fill mean)");
    finest.multiply(p, q);
    const Real step = rz / dot(p, q);
    for (std::size_t i = 0; i < n; ++i) {
      h[i] += step * p[i];
      r[i] -= step * q[i];
    }
    multigrid.cycle(z, r);
    const Real rz_next = dot(r, z);
    const Real beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t i = 0; i < n; ++i)
      p[i] = z[i] + beta * p[i];
    residual_norm = std::sqrt(dot(r, r));
    ++report.iterations;
  }
  report.relative_residual = right_norm > 0 ? residual_norm / right_norm : 0;
  for (std::size_t i = 0; i < n; ++i)
    values[static_cast<std::size_t>(finest.cell[i])] = h[i];
  return report;
}

}  // namespace contactbench
