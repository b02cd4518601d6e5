#include "contactbench/bem/adhesive_lbfgs.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <vector>

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

// The element-wise passes run on the convolution's team, on fixed blocks of kBlock points whose partial
// results are combined in block order: the sums, and so the answer, are the same for every thread count.
constexpr Index kBlock = 4096;

// Partial results of a pass: up to three sums, a largest and a smallest value.
struct Part {
  Real sum[3] = {0, 0, 0};
  Real high = -std::numeric_limits<Real>::infinity(), low = std::numeric_limits<Real>::infinity();
  void add(const Part& o) {
    for (int k = 0; k < 3; ++k)
      sum[k] += o.sum[k];
    high = std::max(high, o.high);
    low = std::min(low, o.low);
  }
};

// body(i, part) for every point i < n, the parts of the blocks combined in block order.
template <class Body>
Part pass(Index n, int threads, const Body& body) {
  const Index blocks = (n + kBlock - 1) / kBlock;
  std::vector<Part> parts(static_cast<std::size_t>(blocks));
#pragma omp parallel for num_threads(threads) schedule(static) if (threads > 1 && blocks > 1)
  for (Index b = 0; b < blocks; ++b) {
    Part& part = parts[static_cast<std::size_t>(b)];
    const Index end = std::min(n, (b + 1) * kBlock);
    for (Index i = b * kBlock; i < end; ++i)
      body(i, part);
  }
  Part total;
  for (const Part& part : parts)
    total.add(part);
  return total;
}

// One block of the two loops' pass: d = (overwrite ? 0 : scale d) + a v, returning w . d when `dot` (the
// branches outside the loop, so that it vectorises: it is half the solve's time at 512^2, perf).
template <bool overwrite, bool dot>
Real update_block(Real* __restrict d, const Real* __restrict v, const Real* __restrict w, Real scale, Real a,
                  Index begin, Index end) {
  Real sum = 0;
#pragma omp simd reduction(+ : sum)
  for (Index i = begin; i < end; ++i) {
    const Real di = (overwrite ? Real(0) : scale * d[i]) + a * v[i];
    d[i] = di;
    if constexpr (dot) sum += w[i] * di;
  }
  return sum;
}

}  // namespace

ExponentialLbfgs::ExponentialLbfgs(const Grid& grid, const HeightMap& heights, Real modulus,
                                   const AdhesionLaw& law, int threads)
    : grid_(grid), heights_(heights), law_(law) {
  if (!grid.periodic) throw Error("adhesive BEM: the projected L-BFGS solves the periodic problem only");
  if (law.model != AdhesionModel::exponential)
    throw Error("adhesive BEM: the projected L-BFGS needs the exponential law");
  // (E*/2)|q| on the periodic grid: the exact inverse of the periodic half-space (both drop q = 0).
  stiffness_ = make_fourier_preconditioner<double>(grid, modulus, threads);
  threads_ = stiffness_->threads();
  shifted_ = HeightMap::Zero(heights.rows(), heights.cols());
  elastic_ = shifted_;
  gradient_ = shifted_;
  traction_ = shifted_;
}

ExponentialLbfgs::~ExponentialLbfgs() = default;

Real ExponentialLbfgs::evaluate(const HeightMap& x, bool load, Real pressure) {
  const Index n = x.size();
  const Real* const xs = x.data();
  const Real* const h = heights_.data();
  Real* const shifted = shifted_.data();
  pass(n, threads_, [&](Index i, Part&) { shifted[i] = xs[i] + h[i]; });  // u up to its mean: g = d - h + u
  stiffness_->apply(shifted_.data(), elastic_.data());
  const Real w = law_.work, rho = law_.range;
  const Real* const elastic = elastic_.data();
  Real* const gradient = gradient_.data();
  const Part sums = pass(n, threads_, [&](Index i, Part& part) {
    const Real e = std::exp(-xs[i] / rho);
    part.sum[0] += shifted[i] * elastic[i];
    part.sum[1] -= w * e;
    part.sum[2] += xs[i];
    gradient[i] = elastic[i] + w / rho * e;
  });
  Real value = (0.5 * sums.sum[0] + sums.sum[1]) / static_cast<Real>(n);
  if (load) value += pressure * sums.sum[2] / static_cast<Real>(n);
  return value;
}

void ExponentialLbfgs::project(HeightMap& x, bool load, Real separation) const {
  const Index count = x.size();
  Real* const xs = x.data();
  if (load) {
    pass(count, threads_, [&](Index i, Part&) { xs[i] = std::max(xs[i], Real(0)); });
    return;
  }
  // max(x - s, 0) with s such that the mean is d: mean(max(x - s, 0)) is convex and falling in s, so Newton's
  // method from the left of the root stays left of it and ends in finitely many steps (piecewise linear).
  const Real n = static_cast<Real>(count);
  const Part range = pass(count, threads_, [&](Index i, Part& part) {
    part.sum[0] += xs[i];
    part.low = std::min(part.low, xs[i]);
  });
  Real s = std::min(range.sum[0] / n - separation, range.low);
  for (int k = 0; k < 200; ++k) {
    const Part above = pass(count, threads_, [&](Index i, Part& part) {
      if (xs[i] > s) {
        part.sum[0] += xs[i] - s;
        part.sum[1] += 1;
      }
    });
    const Real excess = above.sum[0] / n - separation;
    if (excess <= 1e-15 * separation || above.sum[1] == 0) break;
    s += excess * n / above.sum[1];
  }
  pass(count, threads_, [&](Index i, Part&) { xs[i] = std::max(xs[i] - s, Real(0)); });
}

LbfgsOutcome ExponentialLbfgs::solve(bool load, Real value, Real tolerance, Index max_iterations,
                                     HeightMap& gap) {
  LbfgsOutcome out;
  const Real peak = law_.peak_stress();
  const Index n = gap.size(), rows = gap.rows(), cols = gap.cols();
  const int team = threads_;
  project(gap, load, value);
  std::deque<Pair> memory;
  Pair spare;  // the buffers of the next curvature pair (a dropped pair's, once the memory is full)
  HeightMap x = gap, trial(rows, cols), direction(rows, cols), raw(rows, cols);
  HeightMap projected(rows, cols), trial_projected(rows, cols);
  std::vector<unsigned char> bound(static_cast<std::size_t>(n));
  Real largest_pressure = 0;  // the largest repulsive pressure of the state last projected
  // The projected gradient: c added (the load, or the multiplier of mean(g) = d, which the points off the
  // bound fix), 0 where a point at g = 0 is pushed into the bound (the repulsive pressure there); returns c.
  auto project_gradient = [&](const HeightMap& at, const HeightMap& raw_at, HeightMap& result) {
    const Real* const a = at.data();
    const Real* const r = raw_at.data();
    Real* const res = result.data();
    Real c = value;
    if (!load) {
      const Part free = pass(n, team, [&](Index i, Part& part) {
        if (a[i] > 0) {
          part.sum[0] += r[i];
          part.sum[1] += 1;
        }
      });
      c = free.sum[1] > 0 ? -free.sum[0] / free.sum[1] : 0;
    }
    const Part held = pass(n, team, [&](Index i, Part& part) {
      const Real f = r[i] + c;
      const bool on = a[i] == 0 && f > 0;
      bound[static_cast<std::size_t>(i)] = on;
      res[i] = on ? 0 : f;
      if (on) part.high = std::max(part.high, f);
    });
    largest_pressure = std::max(held.high, Real(0));
    return c;
  };
  // direction = scale * direction + a * v (scale 0: overwritten), returning w . direction (0 without w): the
  // two loops below as one pass per pair and loop.
  auto update = [&](Real scale, Real a, const HeightMap* v, const HeightMap* w) {
    Real* const d = direction.data();
    const Real* const vs = v->data();
    const Real* const ws = w ? w->data() : nullptr;
    const Index blocks = (n + kBlock - 1) / kBlock;
    std::vector<Real> parts(static_cast<std::size_t>(blocks));
#pragma omp parallel for num_threads(team) schedule(static) if (team > 1 && blocks > 1)
    for (Index b = 0; b < blocks; ++b) {
      const Index begin = b * kBlock, end = std::min(n, (b + 1) * kBlock);
      Real& part = parts[static_cast<std::size_t>(b)];
      if (scale == 0)
        part = ws ? update_block<true, true>(d, vs, ws, scale, a, begin, end)
                  : update_block<true, false>(d, vs, ws, scale, a, begin, end);
      else
        part = ws ? update_block<false, true>(d, vs, ws, scale, a, begin, end)
                  : update_block<false, false>(d, vs, ws, scale, a, begin, end);
    }
    Real sum = 0;
    for (const Real part : parts)
      sum += part;  // in block order, as pass()
    return sum;
  };
  // Held points stay on the bound; under separation control the step keeps the mean (removed over the free
  // points). The direction is multiplied by `sign` first; returns direction . projected.
  auto restrict = [&](Real sign) {
    Real* const d = direction.data();
    const Real* const pr = projected.data();
    const Part free = pass(n, team, [&](Index i, Part& part) {
      if (bound[static_cast<std::size_t>(i)]) {
        d[i] = 0;
      } else {
        d[i] *= sign;
        part.sum[0] += d[i];
        part.sum[1] += 1;
        part.sum[2] += d[i] * pr[i];
      }
    });
    if (load || free.sum[1] == 0) return free.sum[2];
    const Real mean = free.sum[0] / free.sum[1];
    return pass(n, team,
                [&](Index i, Part& part) {
                  if (!bound[static_cast<std::size_t>(i)]) {
                    d[i] -= mean;
                    part.sum[0] += d[i] * pr[i];
                  }
                })
        .sum[0];
  };
  Real energy = evaluate(x, load, value);
  ++out.evaluations;
  raw.swap(gradient_);
  uniform_ = project_gradient(x, raw, projected);
  // The first step's scale: the inverse of the stiffness's diagonal, K(0) (the Jacobi scaling).
  const Real diagonal = stiffness_->self_response();
  Real gamma = diagonal > 0 ? 1 / diagonal : 1;
  for (;;) {
    // The imbalance in units of the law's peak stress, or of the largest contact pressure where that is
    // larger (as w -> 0 the peak vanishes and the contact's own pressures set the scale).
    {
      const Real* const pr = projected.data();
      const Real* const xs = x.data();
      const Part state = pass(n, team, [&](Index i, Part& part) {
        part.high = std::max(part.high, std::abs(pr[i]));
        part.low = std::min(part.low, xs[i]);
      });
      out.residual = state.high / std::max(peak, largest_pressure);
      if (load && state.low > kSeparatedRanges * law_.range) {
        out.separated = true;
        break;
      }
    }
    if (out.residual <= tolerance) {
      out.converged = true;
      break;
    }
    if (out.iterations >= max_iterations) break;
    ++out.iterations;
    // L-BFGS's two loops on the projected gradient (Nocedal and Wright, algorithm 7.4), each pass fused with
    // the dot product the next step needs.
    const std::size_t m = memory.size();
    std::vector<Real> alpha(m);
    Real dot = m == 0 ? update(0, gamma, &projected, nullptr) : update(0, 1, &projected, &memory[m - 1].s);
    for (std::size_t k = m; k-- > 0;) {
      alpha[k] = memory[k].rho * dot;
      // direction -= alpha_k y_k; after the last pair scaled by gamma, and y_0 . direction for the second
      // loop
      const Real scale = k == 0 ? gamma : 1;
      dot = update(scale, -scale * alpha[k], &memory[k].y, k == 0 ? &memory[0].y : &memory[k - 1].s);
    }
    for (std::size_t k = 0; k < m; ++k) {
      const Real beta = memory[k].rho * dot;
      dot = update(1, alpha[k] - beta, &memory[k].s, k + 1 < m ? &memory[k + 1].y : nullptr);
    }
    if (restrict(-1) >= 0) {  // not a descent direction: steepest descent, memory dropped
      memory.clear();
      update(0, gamma, &projected, nullptr);
      restrict(-1);
    }
    // Backtracking along the projection arc: x(t) = P(x + t d), Armijo on the actual step.
    Real step = 1;
    bool accepted = false;
    Real trial_energy = 0;
    for (int k = 0; k < kMaxHalvings; ++k, step /= 2) {
      const Real* const xs = x.data();
      const Real* const d = direction.data();
      const Real* const pr = projected.data();
      Real* const t = trial.data();
      Real descent = 0;  // projected . (trial - x), projected being n times the gradient of Π (a mean)
      if (load) {
        descent = pass(n, team, [&](Index i, Part& part) {
                    t[i] = std::max(xs[i] + step * d[i], Real(0));
                    part.sum[0] += pr[i] * (t[i] - xs[i]);
                  }).sum[0];
      } else {
        pass(n, team, [&](Index i, Part&) { t[i] = xs[i] + step * d[i]; });
        project(trial, load, value);
        descent = pass(n, team, [&](Index i, Part& part) { part.sum[0] += pr[i] * (t[i] - xs[i]); }).sum[0];
      }
      trial_energy = evaluate(trial, load, value);
      ++out.evaluations;
      if (trial_energy <= energy + kArmijo * descent / static_cast<Real>(n)) {
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
    const Real c = project_gradient(trial, gradient_, trial_projected);
    // The curvature pair from the full force balances (c included); kept only where the energy curves up
    // along the step (the potential is concave, so it may not).
    spare.s.resize(rows, cols);
    spare.y.resize(rows, cols);
    {
      const Real* const xs = x.data();
      const Real* const t = trial.data();
      const Real* const g = gradient_.data();
      const Real* const r = raw.data();
      Real* const ps = spare.s.data();
      Real* const py = spare.y.data();
      const Real shift = c - uniform_;
      const Part curvature = pass(n, team, [&](Index i, Part& part) {
        ps[i] = t[i] - xs[i];
        py[i] = g[i] - r[i] + shift;
        part.sum[0] += ps[i] * py[i];
        part.sum[1] += ps[i] * ps[i];
        part.sum[2] += py[i] * py[i];
      });
      const Real sy = curvature.sum[0];
      if (sy > 1e-12 * std::sqrt(curvature.sum[1] * curvature.sum[2])) {
        spare.rho = 1 / sy;
        gamma = sy / curvature.sum[2];
        memory.push_back(std::move(spare));
        spare = Pair{};
        if (static_cast<Index>(memory.size()) > kMemory) {
          spare = std::move(memory.front());
          memory.pop_front();
        }
      }
    }
    x.swap(trial);
    raw.swap(gradient_);  // gradient_ is written whole by the next evaluation
    projected.swap(trial_projected);
    uniform_ = c;
    energy = trial_energy;
  }
  // The traction of the returned state (gradient_ may hold a rejected trial's).
  evaluate(x, load, value);
  ++out.evaluations;
  uniform_ = project_gradient(x, gradient_, projected);
  const Real* const elastic = elastic_.data();
  Real* const traction = traction_.data();
  pass(n, team, [&](Index i, Part&) { traction[i] = elastic[i] + uniform_; });
  gap.swap(x);
  return out;
}

}  // namespace contactbench
