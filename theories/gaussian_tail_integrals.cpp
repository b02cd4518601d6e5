#include "contactbench/theories/gaussian_tail_integrals.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"

namespace contactbench {
namespace {

// ln sqrt(2 pi).
const Real kLogSqrt2Pi = 0.5 * std::log(2 * pi);
// The integrand is integrated where it exceeds exp(-kLogCut) of its maximum; the part dropped is below
// exp(-kLogCut) / (slope of the exponent there) relative to the integral, under 1e-21.
constexpr Real kLogCut = 50;
// The exponent D(u) has D'' <= -1, so it has fallen by kLogCut within sqrt(2 kLogCut) = 10 of its maximum.
constexpr Real kMaxHalfWidth = 10;

// Tanh-sinh quadrature (Takahasi & Mori 1974) on [a, b]: x in [-kMaxX, kMaxX] maps to
//   u = a + (b - a) / (1 + exp(-pi sinh x)),  du/dx = (b - a) pi cosh x q / (1 + q)^2,  q = exp(-pi sinh
//   |x|).
// The weights at |x| = kMaxX are below 1e-35 (b - a), so the truncation in x is far below round-off.
constexpr Real kMaxX = 4;
constexpr Real kFirstStep = 0.5;
constexpr int kMaxLevel = 10;  // step 0.5 / 2^10: far more than the range [-10, 40] needs (levels 4 to 6)
constexpr int kMinLevel = 3;
// Stop when a halving of the step changes the sum by less than this: tanh-sinh doubles the correct digits per
// level, so the last sum is then correct to round-off.
constexpr Real kLevelChange = 1e-10;

// Nodes of one level: the distance of the pair of nodes from the nearer end and their weight, both for
// an interval of unit length; level 0 holds x = 0 (one node, counted once) and k h for k = 1, 2, ...,
// level j > 0 the odd multiples of h = kFirstStep / 2^j.
struct Node {
  Real offset;
  Real weight;
};

std::vector<std::vector<Node>> make_nodes() {
  std::vector<std::vector<Node>> levels(kMaxLevel + 1);
  for (int level = 0; level <= kMaxLevel; ++level) {
    const Real h = kFirstStep / static_cast<Real>(1 << level);
    const int count = static_cast<int>(kMaxX / h + 0.5);
    for (int k = level == 0 ? 0 : 1; k <= count; k += level == 0 ? 1 : 2) {
      const Real x = k * h;
      const Real q = std::exp(-pi * std::sinh(x));
      levels[level].push_back({q / (1 + q), pi * std::cosh(x) * q / ((1 + q) * (1 + q))});
    }
  }
  return levels;
}

const std::vector<std::vector<Node>>& nodes() {
  static const std::vector<std::vector<Node>> table = make_nodes();
  return table;
}

// int_a^b g(u) du for a positive g with at most integrable endpoint singularities.
template <class G>
Real tanh_sinh(const G& g, Real a, Real b) {
  const Real length = b - a;
  const auto& levels = nodes();
  auto pair = [&](const Node& node) {
    const Real offset = length * node.offset;
    return node.weight * (g(a + offset) + g(b - offset));
  };
  // Level 0: x = 0 is a single node (the pair formula counts the midpoint twice).
  Real sum = 0;
  for (std::size_t k = 0; k < levels[0].size(); ++k)
    sum += k == 0 ? 0.5 * pair(levels[0][k]) : pair(levels[0][k]);
  Real h = kFirstStep;
  Real integral = length * h * sum;
  for (int level = 1; level <= kMaxLevel; ++level) {
    h *= 0.5;
    Real added = 0;
    for (const Node& node : levels[level])
      added += pair(node);
    const Real previous = integral;
    sum += added;
    integral = length * h * sum;
    if (level >= kMinLevel && std::abs(integral - previous) <= kLevelChange * integral) break;
  }
  return integral;
}

std::string str(Real value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

// ln F_n(t) from F_n(t) = (2 pi)^(-1/2) int_0^inf u^n exp(-(t + u)^2/2) du (s = t + u), written as
// exp(E(u*)) int exp(D(u)) du with E(u) = n ln u - (t + u)^2/2 and D(u) = E(u) - E(u*) <= 0, u* the maximum.
Real log_tail_by_quadrature(Real n, Real t) {
  // u* solves n/u = t + u. Both branches avoid cancellation; s* = t + u* likewise.
  Real peak = 0, peak_s = 0;
  if (n == 0) {
    peak = t < 0 ? -t : 0;
    peak_s = t < 0 ? 0 : t;
  } else {
    const Real root =
        std::abs(t) > 1 ? std::abs(t) * std::sqrt(1 + 4 * n / (t * t)) : std::sqrt(t * t + 4 * n);
    peak = t >= 0 ? 2 * n / (t + root) : 0.5 * (root - t);
    peak_s = t >= 0 ? t + peak : 2 * n / (root - t);
  }
  // D(u) = n ln(u/u*) - (u - u*)(s* + (u - u*)/2), with s* = t + u*: no large terms cancel.
  auto exponent = [n, peak, peak_s](Real u) {
    const Real du = u - peak;
    const Real power = n == 0 ? 0 : n * std::log(u / peak);
    return power - du * (peak_s + 0.5 * du);
  };
  auto integrand = [&exponent](Real u) { return std::exp(exponent(u)); };

  // The ends of the interval where D > -kLogCut: a step out from u* that reaches below the cut (doubling
  // from a scale that fits the integrand's decay, never beyond kMaxHalfWidth), then bisection.
  auto edge = [&exponent, peak](Real direction, Real first_step) {
    Real inside = 0, outside = first_step;
    while (outside < kMaxHalfWidth && exponent(peak + direction * outside) > -kLogCut) {
      inside = outside;
      outside *= 2;
    }
    if (outside >= kMaxHalfWidth) outside = kMaxHalfWidth;
    for (int i = 0; i < 30; ++i) {  // 1e-9 of the step: the end need not be exact, only beyond the cut
      const Real mid = 0.5 * (inside + outside);
      (exponent(peak + direction * mid) > -kLogCut ? inside : outside) = mid;
    }
    return peak + direction * outside;
  };
  const Real upper = edge(+1, t > 1 ? kLogCut / t : 1);
  // Below u* the interval reaches down to 0 (keeping the u^n singularity at an end) unless the integrand is
  // negligible there, which happens only far out at negative t.
  const Real lower = peak > kMaxHalfWidth ? edge(-1, 1) : 0;

  const Real peak_exponent = (n == 0 ? 0 : n * std::log(peak)) - 0.5 * peak_s * peak_s;
  return peak_exponent - kLogSqrt2Pi + std::log(tanh_sinh(integrand, lower, upper));
}

}  // namespace

Real log_gaussian_tail_integral(Real n, Real t) {
  if (!(std::isfinite(n) && n >= 0))
    throw Error("gaussian tail integral F_n(t): n must be finite and >= 0, got " + str(n));
  if (!std::isfinite(t)) throw Error("gaussian tail integral F_n(t): t must be finite, got " + str(t));
  // Closed forms (docs/theory.md section 5) where they are well conditioned: erfc keeps full relative
  // accuracy in this range, and phi - t F_0 loses at most a factor 3 (at t = 1) to cancellation.
  if (n == 0 && t <= 2) return std::log(0.5 * std::erfc(t / std::numbers::sqrt2));
  if (n == 1 && t <= 1) {
    const Real f0 = 0.5 * std::erfc(t / std::numbers::sqrt2);
    return std::log(std::exp(-0.5 * t * t - kLogSqrt2Pi) - t * f0);
  }
  return log_tail_by_quadrature(n, t);
}

Real gaussian_tail_integral(Real n, Real t) {
  return std::exp(log_gaussian_tail_integral(n, t));
}

}  // namespace contactbench
