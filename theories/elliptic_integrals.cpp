#include "contactbench/theories/elliptic_integrals.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "contactbench/core/error.hpp"
#include "contactbench/theories/number_text.hpp"

namespace contactbench {
namespace {

// Carlson (1995), section 2: the duplication stops when 4^-n Q < |A_n| with Q = (3 r)^(-1/6) max|A_0 - x_0|
// (R_F) or (r/4)^(-1/6) max|A_0 - x_0| (R_D); the truncated series below (to order 7) then errs by less than
// r.
constexpr Real kRelativeError = 1e-17;
// A safety cap on the duplication steps: each divides the spread by 4, 60 steps reach 1e-36.
constexpr int kMaxDuplications = 60;

bool nonnegative(Real v) {
  return std::isfinite(v) && v >= 0;
}

// A_n and 4^-n after Carlson's duplication (1995, eq. 2.2, shared by R_F and R_D).
struct Duplicated {
  Real a, scale;
};

// Duplicates until 4^-n Q < |A_n|: x, y, z and their mean a each become (v + lambda)/4, lambda = sqrt(x y) +
// sqrt(y z) + sqrt(z x). Before each step, term(4^-n, sqrt(z), z, lambda) sees it (R_D sums one term a step).
template <typename Term>
Duplicated duplicate(Real x, Real y, Real z, Real a, Real q, Term term) {
  Real scale = 1;  // 4^-n
  for (int n = 0; n < kMaxDuplications && scale * q >= std::abs(a); ++n) {
    const Real sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
    const Real lambda = sx * sy + sy * sz + sz * sx;
    term(scale, sz, z, lambda);
    a = (a + lambda) / 4;
    x = (x + lambda) / 4;
    y = (y + lambda) / 4;
    z = (z + lambda) / 4;
    scale /= 4;
  }
  return {a, scale};
}

}  // namespace

// Carlson (1995) eqs. (2.2)-(2.4); the series is DLMF 19.36.1.
Real carlson_rf(Real x, Real y, Real z) {
  if (!(nonnegative(x) && nonnegative(y) && nonnegative(z)) || (x == 0) + (y == 0) + (z == 0) > 1)
    throw Error("carlson_rf: arguments must be finite and >= 0 with at most one 0, got " + format_number(x) +
                ", " + format_number(y) + ", " + format_number(z));
  const Real a0 = (x + y + z) / 3;
  const Real q = std::pow(3 * kRelativeError, -1.0 / 6.0) *
                 std::max({std::abs(a0 - x), std::abs(a0 - y), std::abs(a0 - z)});
  const auto [a, scale] = duplicate(x, y, z, a0, q, [](Real, Real, Real, Real) {});
  // X = (A_0 - x_0)/(4^n A_n), Y likewise, Z = -X - Y.
  const Real xx = (a0 - x) * scale / a, yy = (a0 - y) * scale / a;
  const Real zz = -(xx + yy);
  const Real e2 = xx * yy - zz * zz, e3 = xx * yy * zz;
  return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44 - 5 * e2 * e2 * e2 / 208 +
          3 * e3 * e3 / 104 + e2 * e2 * e3 / 16) /
         std::sqrt(a);
}

// Carlson (1995) eqs. (2.28)-(2.33); the series is DLMF 19.36.2.
Real carlson_rd(Real x, Real y, Real z) {
  if (!(nonnegative(x) && nonnegative(y) && std::isfinite(z) && z > 0) || (x == 0 && y == 0))
    throw Error("carlson_rd: x, y must be finite and >= 0, not both 0, z finite and > 0, got " +
                format_number(x) + ", " + format_number(y) + ", " + format_number(z));
  const Real a0 = (x + y + 3 * z) / 5;
  const Real q = std::pow(kRelativeError / 4, -1.0 / 6.0) *
                 std::max({std::abs(a0 - x), std::abs(a0 - y), std::abs(a0 - z)});
  Real sum = 0;
  const auto [a, scale] = duplicate(x, y, z, a0, q, [&sum](Real step_scale, Real sz, Real zn, Real lambda) {
    sum += step_scale / (sz * (zn + lambda));
  });
  // X = (A_0 - x_0)/(4^n A_n), Y likewise, Z = -(X + Y)/3.
  const Real xx = (a0 - x) * scale / a, yy = (a0 - y) * scale / a;
  const Real zz = -(xx + yy) / 3;
  const Real xy = xx * yy, z2 = zz * zz;
  const Real e2 = xy - 6 * z2, e3 = (3 * xy - 8 * z2) * zz, e4 = 3 * (xy - z2) * z2, e5 = xy * z2 * zz;
  const Real series =
      1 - 3 * e2 / 14 + e3 / 6 + 9 * e2 * e2 / 88 - 3 * e4 / 22 - 9 * e2 * e3 / 52 + 3 * e5 / 26;
  return 3 * sum + scale * series / (a * std::sqrt(a));
}

// DLMF 19.25.1: K(m) = R_F(0, 1 - m, 1).
Real elliptic_k(Real m) {
  if (!(m >= 0 && m <= 1))
    throw Error("elliptic_k: the parameter m must lie in [0, 1], got " + format_number(m));
  if (m == 1) return std::numeric_limits<Real>::infinity();
  return carlson_rf(0, 1 - m, 1);
}

// DLMF 19.25.1: E(m) = R_F(0, 1 - m, 1) - (m/3) R_D(0, 1 - m, 1); both terms are positive and the
// difference is at least E(m) >= 1 while K <= 1 + ln(4/sqrt(1 - m)): a loss of at most log10(K) digits.
Real elliptic_e(Real m) {
  if (!(m >= 0 && m <= 1))
    throw Error("elliptic_e: the parameter m must lie in [0, 1], got " + format_number(m));
  if (m == 1) return 1;
  const Real y = 1 - m;
  return carlson_rf(0, y, 1) - m / 3 * carlson_rd(0, y, 1);
}

// DLMF 19.25.1: K - E = (m/3) R_D(0, 1 - m, 1).
Real elliptic_k_minus_e_over_m(Real m) {
  if (!(m >= 0 && m < 1))
    throw Error("elliptic_k_minus_e_over_m: the parameter m must lie in [0, 1), got " + format_number(m));
  return carlson_rd(0, 1 - m, 1) / 3;
}

}  // namespace contactbench
