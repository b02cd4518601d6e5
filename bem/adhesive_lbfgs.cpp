#include "contactbench/bem/adhesive_lbfgs.hpp"

#include <algorithm>
#include <cmath>
#include <deque>

#include "contactbench/bem/fourier_preconditioner.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// Curvature pairs kept (L-BFGS's memory; 5 to 20 is the usual range, results insensitive within it).
constexpr Index kMemory = 10;
// Armijo's sufficient decrease, and the halvings of the step before the memory is dropped.
constexpr Real kArmijo = 1e-4;
constexpr int kMaxHalvings = 40;
// Load control: no contact and every gap beyond this many ranges (attraction below e^-30 of its peak): no
// state in contact carries the load, the surfaces separate.
constexpr Real kSeparatedRanges = 30;

struct Pair {
  HeightMap s, y;
  Real rho = 0;
};

}  // namespace

ExponentialLbfgs::ExponentialLbfgs(const Grid& grid, const HeightMap& heights, Real modulus,
                                   const AdhesionLaw& law, int threads)
    : grid_(grid), heights_(heights), law_(law) {
  if (!grid.periodic) throw Error("adhesive BEM: the projected L-BFGS solves the periodic problem only");
  if (law.model != AdhesionModel::exponential)
    throw Error("adhesive BEM: the projected L-BFGS needs the exponential law");
  // (E*/2)|q| on the periodic grid: the exact inverse of the periodic half-space (both drop q = 0).
  stiffness_ = make_fourier_preconditioner<double>(grid, modulus, threads);
  shifted_ = HeightMap::Zero(heights.rows(), heights.cols());
  elastic_ = shifted_;
  gradient_ = shifted_;
  traction_ = shifted_;
}

ExponentialLbfgs::~ExponentialLbfgs() = default;

Real ExponentialLbfgs::evaluate(const HeightMap& x, bool load, Real pressure) {
  shifted_ = x + heights_;  // u up to its mean: g = d - h + u
  stiffness_->apply(shifted_.data(), elastic_.data());
  const Real w = law_.work, rho = law_.range;
  const Index n = x.size();
  Real elastic = 0, potential = 0;
  for (Index i = 0; i < n; ++i) {
    const Real e = std::exp(-x.data()[i] / rho);
    elastic += shifted_.data()[i] * elastic_.data()[i];
    potential -= w * e;
    gradient_.data()[i] = elastic_.data()[i] + w / rho * e;
  }
  Real value = (0.5 * elastic + potential) / static_cast<Real>(n);
  if (load) value += pressure * x.mean();
  return value;
}

void ExponentialLbfgs::project(HeightMap& x, bool load, Real separation) const {
  if (load) {
    x = x.max(0);
    return;
  }
  // max(x - s, 0) with s such that the mean is d: mean(max(x - s, 0)) is convex and falling in s, so Newton's
  // method from the left of the root stays left of it and ends in finitely many steps (piecewise linear).
  const Real n = static_cast<Real>(x.size());
  Real s = std::min(x.mean() - separation, x.minCoeff());
  for (int k = 0; k < 200; ++k) {
    Real sum = 0, count = 0;
    for (Index i = 0; i < x.size(); ++i)
      if (x.data()[i] > s) {
        sum += x.data()[i] - s;
        ++count;
      }
    const Real excess = sum / n - separation;
    if (excess <= 1e-15 * separation || count == 0) break;
    s += excess * n / count;
  }
  x = (x - s).max(0);
}

LbfgsOutcome ExponentialLbfgs::solve(bool load, Real value, Real tolerance, Index max_iterations,
                                     HeightMap& gap) {
  LbfgsOutcome out;
  const Real peak = law_.peak_stress();
  const Index n = gap.size();
  project(gap, load, value);
  std::deque<Pair> memory;
  HeightMap x = gap, trial(gap.rows(), gap.cols()), direction(gap.rows(), gap.cols());
  HeightMap projected(gap.rows(), gap.cols()), trial_projected(gap.rows(), gap.cols());
  std::vector<unsigned char> bound(static_cast<std::size_t>(n));
  Real largest_pressure = 0;  // the largest repulsive pressure of the state last projected
  // The projected gradient: c added (the load, or the multiplier of mean(g) = d, which the points off the
  // bound fix), 0 where a point at g = 0 is pushed into the bound (the repulsive pressure there); returns c.
  auto project_gradient = [&](const HeightMap& at, const HeightMap& raw, HeightMap& result) {
    Real c = value;
    if (!load) {
      Real sum = 0, count = 0;
      for (Index i = 0; i < n; ++i)
        if (at.data()[i] > 0) {
          sum += raw.data()[i];
          ++count;
        }
      c = count > 0 ? -sum / count : 0;
    }
    largest_pressure = 0;
    for (Index i = 0; i < n; ++i) {
      const Real r = raw.data()[i] + c;
      const bool held = at.data()[i] == 0 && r > 0;
      bound[static_cast<std::size_t>(i)] = held;
      result.data()[i] = held ? 0 : r;
      if (held) largest_pressure = std::max(largest_pressure, r);
    }
    return c;
  };
  Real energy = evaluate(x, load, value);
  ++out.evaluations;
  HeightMap raw = gradient_;
  uniform_ = project_gradient(x, raw, projected);
  // The first step's scale: the inverse of the stiffness's diagonal, K(0) (the Jacobi scaling).
  const Real diagonal = stiffness_->self_response();
  Real gamma = diagonal > 0 ? 1 / diagonal : 1;
  for (;;) {
    // The imbalance in units of the law's peak stress, or of the largest contact pressure where that is
    // larger (as w -> 0 the peak vanishes and the contact's own pressures set the scale).
    out.residual = projected.abs().maxCoeff() / std::max(peak, largest_pressure);
    if (load && x.minCoeff() > kSeparatedRanges * law_.range) {
      out.separated = true;
      break;
    }
    if (out.residual <= tolerance) {
      out.converged = true;
      break;
    }
    if (out.iterations >= max_iterations) break;
    ++out.iterations;
    // L-BFGS's two loops on the projected gradient (Nocedal and Wright, algorithm 7.4).
    direction = projected;
    std::vector<Real> alpha(memory.size());
    for (std::size_t k = memory.size(); k-- > 0;) {
      alpha[k] = memory[k].rho * (memory[k].s * direction).sum();
      direction -= alpha[k] * memory[k].y;
    }
    direction *= gamma;
    for (std::size_t k = 0; k < memory.size(); ++k) {
      const Real beta = memory[k].rho * (memory[k].y * direction).sum();
      direction += (alpha[k] - beta) * memory[k].s;
    }
    direction = -direction;
    // Held points stay on the bound; under separation control the step keeps the mean (removed over the
    // free points).
    auto restrict = [&](HeightMap& d) {
      Real sum = 0, count = 0;
      for (Index i = 0; i < n; ++i)
        if (bound[static_cast<std::size_t>(i)])
          d.data()[i] = 0;
        else {
          sum += d.data()[i];
          ++count;
        }
      if (!load && count > 0)
        for (Index i = 0; i < n; ++i)
          if (!bound[static_cast<std::size_t>(i)]) d.data()[i] -= sum / count;
    };
    restrict(direction);
    if ((direction * projected).sum() >= 0) {  // not a descent direction: steepest descent, memory dropped
      memory.clear();
      direction = -gamma * projected;
      restrict(direction);
    }
    // Backtracking along the projection arc: x(t) = P(x + t d), Armijo on the actual step.
    Real step = 1;
    bool accepted = false;
    Real trial_energy = 0;
    for (int k = 0; k < kMaxHalvings; ++k, step /= 2) {
      trial = x + step * direction;
      project(trial, load, value);
      trial_energy = evaluate(trial, load, value);
      ++out.evaluations;
      // (projected is n times the gradient of Π, a mean over the points)
      if (trial_energy <= energy + kArmijo * (projected * (trial - x)).sum() / static_cast<Real>(n)) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      if (memory.empty()) break;  // not even steepest descent decreases Π: stalled, marked not converged
      memory.clear();
      gamma = diagonal > 0 ? 1 / diagonal : 1;
      continue;
    }
    HeightMap new_raw = gradient_;
    const Real c = project_gradient(trial, new_raw, trial_projected);
    // The curvature pair from the full force balances (c included); kept only where the energy curves up
    // along the step (the potential is concave, so it may not).
    Pair pair;
    pair.s = trial - x;
    pair.y = (new_raw + c) - (raw + uniform_);
    const Real sy = (pair.s * pair.y).sum();
    if (sy > 1e-12 * std::sqrt((pair.s.square().sum()) * (pair.y.square().sum()))) {
      pair.rho = 1 / sy;
      gamma = sy / pair.y.square().sum();
      memory.push_back(std::move(pair));
      if (static_cast<Index>(memory.size()) > kMemory) memory.pop_front();
    }
    x = trial;
    raw = new_raw;
    projected = trial_projected;
    uniform_ = c;
    energy = trial_energy;
  }
  // The traction of the returned state (gradient_ may hold a rejected trial's).
  evaluate(x, load, value);
  ++out.evaluations;
  uniform_ = project_gradient(x, gradient_, projected);
  traction_ = elastic_ + uniform_;
  gap = x;
  return out;
}

}  // namespace contactbench
