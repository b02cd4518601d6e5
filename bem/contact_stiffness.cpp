#include "contactbench/bem/contact_stiffness.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/bem/half_space.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench {

namespace {

using Multiplier = Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The preconditioner's multiplier, P G^-1 P with the periodic inverse E* |q|/2 on the grid's own lattice (the
// mean mode given that of the smallest wavevector, to stay positive), the transform pair's 1/(nx ny) folded
// in: the Fourier preconditioner of docs/solvers.md, which takes out the 1/|q| spread of G's spectrum that
// makes plain CG slow on fine grids. Circular on the grid for a non-periodic grid too (the restriction to
// C is applied around it either way).
Multiplier inverse_symbol(const Grid& grid, Real modulus) {
  const HalfLattice lattice(grid);
  const auto qx = lattice.qx_row();
  const auto qy = lattice.qy_column();
  const Real smallest = std::min(grid.dqx(), grid.dqy());
  Multiplier inverse(grid.ny, grid.nx / 2 + 1);
  for (Index row = 0; row < grid.ny; ++row)
    for (Index col = 0; col < inverse.cols(); ++col)
      inverse(row, col) =
          modulus / 2 * std::max(std::hypot(qx(col), qy(row)), smallest) / static_cast<Real>(grid.points());
  return inverse;
}

double sum_of(const std::vector<double>& partials) {
  double sum = 0;
  for (const double part : partials)
    sum += part;  // in thread order: the same sum from run to run
  return sum;
}

}  // namespace

// The two convolutions of an iteration (the operator G and the preconditioner's filter) carry the CG's
// element-wise work in their row callbacks (bem/convolution.hpp), so an iteration is two FFT pairs and no
// separate pass over full arrays: the operator pass forms the direction d = z + beta d as it reads it,
// takes d.Gd from the spectrum (d vanishes off C, so d.Gd = d.A d) and, in its output rows, steps x and r
// and sums r.r; the filter pass reads r and writes z = P F r, summing r.z.
struct ContactStiffnessSolver::Impl {
  Impl(const Grid& grid_in, Real modulus, std::optional<Real> hardness, int threads,
       StiffnessOptions options_in)
      : grid(grid_in),
        options(options_in),
        // Plastic points (p at the cap H, to round-off) keep their pressure: only the elastic contact moves.
        cap(hardness ? *hardness * (1 - 1e-12) : std::numeric_limits<Real>::infinity()),
        operator_g(make_half_space_convolution<double>(grid_in, modulus, threads)),
        filter(std::make_unique<Convolution<double>>(grid_in.nx, grid_in.ny, false, threads)) {
    filter->set_multiplier(inverse_symbol(grid, modulus));
  }

  ContactStiffness solve(const HeightMap& pressure);
  double operator_pass(double beta, double rz);  // returns r.r after the step
  double filter_pass();                          // returns r.z

  Grid grid;
  StiffnessOptions options;
  Real cap;
  std::unique_ptr<Convolution<double>> operator_g, filter;
  // The state of a solve: the set C (1 on it), the response x, the residual r = 1 - A x, the filtered
  // residual z, the direction d; all ny x nx row-major, 0 off C.
  std::vector<std::uint8_t> in;
  std::vector<double> x, r, z, d;
};

double ContactStiffnessSolver::Impl::operator_pass(double beta, double rz) {
  using Conv = Convolution<double>;
  const Index nx = grid.nx;
  std::vector<double> partials(static_cast<std::size_t>(operator_g->threads()), 0.0);
  double step = 0;
  auto direction_in = [&](Index first, Index rows, double* buffer, Index ld, int) {
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      for (Index col = 0; col < nx; ++col) {
        const std::size_t k = static_cast<std::size_t>(i0 + col);
        const double direction = in[k] ? z[k] + beta * d[k] : 0.0;
        d[k] = direction;
        buffer[y * ld + col] = direction;
      }
    }
  };
  auto step_length = [&](double d_gd) { step = d_gd > 0 ? rz / d_gd : 0.0; };
  auto stepped_out = [&](Index first, Index rows, const double* buffer, Index ld, int thread) {
    double rr = 0;
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      for (Index col = 0; col < nx; ++col) {
        const std::size_t k = static_cast<std::size_t>(i0 + col);
        if (!in[k]) continue;  // A = P G P: the response off C is not the operator's
        x[k] += step * d[k];
        r[k] -= step * buffer[y * ld + col];
        rr += r[k] * r[k];
      }
    }
    partials[static_cast<std::size_t>(thread)] += rr;
  };
  operator_g->apply(Conv::Producer(direction_in), Conv::Consumer(stepped_out), {}, true,
                    Conv::ProductHook(step_length));
  return sum_of(partials);
}

double ContactStiffnessSolver::Impl::filter_pass() {
  using Conv = Convolution<double>;
  const Index nx = grid.nx;
  std::vector<double> partials(static_cast<std::size_t>(filter->threads()), 0.0);
  auto residual_in = [&](Index first, Index rows, double* buffer, Index ld, int) {
    for (Index y = 0; y < rows; ++y)
      std::copy_n(r.data() + (first + y) * nx, nx, buffer + y * ld);  // r is 0 off C
  };
  auto filtered_out = [&](Index first, Index rows, const double* buffer, Index ld, int thread) {
    double rz = 0;
    for (Index y = 0; y < rows; ++y) {
      const Index i0 = (first + y) * nx;
      for (Index col = 0; col < nx; ++col) {
        const std::size_t k = static_cast<std::size_t>(i0 + col);
        z[k] = in[k] ? buffer[y * ld + col] : 0.0;
        rz += r[k] * z[k];
      }
    }
    partials[static_cast<std::size_t>(thread)] += rz;
  };
  filter->apply(Conv::Producer(residual_in), Conv::Consumer(filtered_out));
  return sum_of(partials);
}

ContactStiffness ContactStiffnessSolver::Impl::solve(const HeightMap& pressure) {
  ContactStiffness result;
  const Index points = grid.points();
  const auto size = static_cast<std::size_t>(points);
  in.assign(size, 0);
  Index on_set = 0;
  for (Index k = 0; k < points; ++k) {
    const Real p = pressure.data()[k];
    in[static_cast<std::size_t>(k)] = p > 0 && p < cap;
    on_set += in[static_cast<std::size_t>(k)];
  }
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
  // Preconditioned conjugate gradients on A = P G P (P: restriction to C), right-hand side b = 1 on C, from
  // x = 0.
  x.assign(size, 0.0);
  d.assign(size, 0.0);
  z.assign(size, 0.0);
  r.resize(size);
  for (std::size_t k = 0; k < size; ++k)
    r[k] = in[k];
  const Real b_norm = std::sqrt(static_cast<Real>(on_set));
  Real rr = static_cast<Real>(on_set);
  Real rz = filter_pass();
  Real beta = 0;
  for (Index it = 0; it < options.max_iterations; ++it) {
    if (std::sqrt(rr) <= options.tolerance * b_norm) {
      result.converged = true;
      break;
    }
    rr = operator_pass(beta, rz);
    const Real rz_next = filter_pass();
    beta = rz_next / rz;
    rz = rz_next;
    result.iterations = it + 1;
  }
  result.residual = std::sqrt(rr) / b_norm;
  if (!result.converged) result.converged = result.residual <= options.tolerance;
  // The energy estimate (header): b.x + x.r, whose error is quadratic in r (from x = 0, x.r vanishes in
  // exact arithmetic, r being orthogonal to the Krylov space x lies in; kept for the round-off).
  Real sum_x = 0, x_r = 0;
  for (std::size_t k = 0; k < size; ++k) {
    sum_x += x[k];
    x_r += x[k] * r[k];
  }
  result.stiffness = (sum_x + x_r) / static_cast<Real>(points);
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
