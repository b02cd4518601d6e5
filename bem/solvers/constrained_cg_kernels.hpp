// The element-wise work of the constrained CG's fused passes (bem/solvers/polonsky_keer_solver.cpp and
// preconditioned_cg_solver.cpp), a row at a time, and the per-thread partial sums they leave. Internal:
// include it only from the one file that calls each kernel (each is compiled twice, below).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench::cg {

// The element-wise kernels are compiled twice, for SSE2 (any x86-64) and AVX2, the better one chosen at load
// time (g++'s function multi-versioning): twice the lanes on the machines that have them. No FMA, so both
// round alike; sums over lanes are ordered differently, so results agree between the two to round-off only.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define CB_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define CB_KERNEL
#endif

// What one thread sums during one pass: one cache line each, combined in thread order after the pass, so
// that for a fixed thread count the sums (and so the iterates) are the same from run to run.
struct alignas(64) Partial {
  double change = 0, sum = 0;            // sum |p - p_old|, sum p
  double elastic = 0, plastic = 0;       // node counts
  double shift = 0, s1 = 0, s2 = 0;      // sum (g - shift), sum (g - shift)^2 over the elastic set
  bool has_shift = false;                // see gap_rows
  double gt = 0, t_sum = 0, r_sum = 0;   // sum g t, sum t, sum r over the elastic set
  double q_sum = 0, entered = 0;         // sum of the new pressure, nodes that entered or left the set
  double rz = 0, z_sum = 0, rr_sum = 0;  // preconditioned: sum r z, sum z, sum r over the elastic set
  double tt = 0;                         // preconditioned: sum t^2
  void clear() { *this = Partial{}; }
};

// The gap's moments on the elastic set, and the pressure's sum and change, over all threads.
struct Moments {
  double change = 0, sum = 0, elastic = 0, plastic = 0, g_mean = 0, g_norm = 0;
};

// The kernels are branch-free (restrict: nothing aliases), so that the compiler vectorises: the sets are
// comparisons of the pressure, not stored masks.

// Consuming u: gap g = s u - h + offset, change of the pressure, and the moments of the gap on the elastic
// set. Under load control the mean and the sum of squares about the mean are needed; a sum of squares
// about a fixed shift loses nothing when the shift is one of the values (the spread about it is the spread
// about the mean), so each thread shifts by the first elastic gap it meets and the threads' moments are
// combined exactly (Chan et al.). Separation control needs no mean: the sum of g^2.
template <bool kLoad, bool kHard, class T>
CB_KERNEL void gap_rows(Partial& part, const T* __restrict qn, const T* __restrict qo, const T* __restrict u,
                        const T* __restrict h, T* __restrict g, Index nx, T s_new, T s_old, T offset,
                        T hardness) {
  if (kLoad && !part.has_shift) {
    for (Index x = 0; x < nx; ++x)
      if (qn[x] > 0) {
        part.shift = static_cast<double>(s_new * u[x] - h[x] + offset);
        part.has_shift = true;
        break;
      }
  }
  const double shift = kLoad ? part.shift : 0.0;
  double change = 0, sum = 0, s1 = 0, s2 = 0, elastic = 0, plastic = 0;
#pragma omp simd reduction(+ : change, sum, s1, s2, elastic, plastic)
  for (Index x = 0; x < nx; ++x) {
    const T p = s_new * qn[x];
    change += static_cast<double>(std::abs(p - s_old * qo[x]));
    sum += static_cast<double>(p);
    const T gv = s_new * u[x] - h[x] + offset;
    g[x] = gv;
    const bool in = kHard ? (p > 0) & (p < hardness) : p > 0;
    const double d = in ? static_cast<double>(gv) - shift : 0.0;
    s1 += d;
    s2 += d * d;
    elastic += in ? 1.0 : 0.0;
    if constexpr (kHard) plastic += p >= hardness ? 1.0 : 0.0;
  }
  part.change += change;
  part.sum += sum;
  part.s1 += s1;
  part.s2 += s2;
  part.elastic += elastic;
  part.plastic += plastic;
}

// t = g - gbar + beta t on the elastic set (0 elsewhere), into the operator's input; sums (g - gbar) t, t.
template <bool kHard, class T>
CB_KERNEL void direction_row(Partial& part, const T* __restrict q, const T* __restrict g, T* __restrict t,
                             T* __restrict out, Index nx, T s, T gbar, T beta, T hardness) {
  double gt = 0, t_sum = 0;
#pragma omp simd reduction(+ : gt, t_sum)
  for (Index x = 0; x < nx; ++x) {
    const bool in = kHard ? (q[x] > 0) & (s * q[x] < hardness) : q[x] > 0;
    const T gc = g[x] - gbar;
    const T tv = in ? gc + beta * t[x] : T(0);
    t[x] = tv;
    out[x] = tv;
    gt += static_cast<double>(gc * tv);
    t_sum += static_cast<double>(tv);
  }
  part.gt += gt;
  part.t_sum += t_sum;
}

// Consuming r = G t: its sum on the contact set.
template <class T>
CB_KERNEL void response_row(Partial& part, const T* __restrict q, const T* __restrict r, Index nx) {
  double r_sum = 0;
#pragma omp simd reduction(+ : r_sum)
  for (Index x = 0; x < nx; ++x) {
    const double v = static_cast<double>(r[x]);
    r_sum += q[x] > 0 ? v : 0.0;
  }
  part.r_sum += r_sum;
}

// The update q = max(p - tau t, 0) (capped at H); nodes out of contact that the surface penetrates enter
// with -tau_enter g (PK eq. 14), plastic nodes that open leave with H - tau_enter g.
template <bool kHard, class T>
CB_KERNEL void update_row(Partial& part, const T* __restrict qc, const T* __restrict t, const T* __restrict g,
                          T* __restrict qn, T* __restrict out, Index nx, T s, T tau, T tau_enter, T gbar,
                          T hardness) {
  double q_sum = 0, entered = 0;
#pragma omp simd reduction(+ : q_sum, entered)
  for (Index x = 0; x < nx; ++x) {
    const T p = s * qc[x];
    const T gc = g[x] - gbar;
    const T moved_to = -tau_enter * gc;  // entering: the penetration times the step
    T v;
    bool moved;
    if constexpr (kHard) {
      // t = 0 off the elastic set, so the step leaves plastic nodes at H and the rest at 0. Nodes entering
      // or leaving move at most halfway into [0, H]: into the elastic set, whose conjugate gradient then
      // accounts for how they press on each other. (Moved all the way, to H or to 0, as PK's entry step
      // would, many nodes at once overshoot together: a cycle between all plastic and all released.)
      const T stepped = std::min(std::max(p - tau * t[x], T(0)), hardness);
      const bool enter = (p <= 0) & (gc < 0), leave = (p >= hardness) & (gc > 0);
      const T middle = hardness / 2;
      v = enter ? std::min(moved_to, middle) : (leave ? std::max(hardness + moved_to, middle) : stepped);
      moved = enter | leave;
    } else {
      const T stepped = std::max(p - tau * t[x], T(0));
      moved = (p <= 0) & (gc < 0);
      v = moved ? moved_to : stepped;
    }
    qn[x] = v;
    out[x] = v;
    q_sum += static_cast<double>(v);
    entered += moved ? 1.0 : 0.0;
  }
  part.q_sum += q_sum;
  part.entered += entered;
}

// The threads' partial sums of a gap pass combined, in thread order.
template <bool kLoad>
Moments combine_moments(const std::vector<Partial>& partial) {
  Moments m;
  for (const Partial& part : partial) {
    m.change += part.change;
    m.sum += part.sum;
    m.elastic += part.elastic;
    m.plastic += part.plastic;
  }
  if (m.elastic == 0) return m;
  if constexpr (kLoad) {
    double mean = 0;
    for (const Partial& part : partial)
      if (part.elastic > 0) mean += part.elastic * part.shift + part.s1;
    mean /= m.elastic;
    double norm = 0;
    for (const Partial& part : partial)
      if (part.elastic > 0) {
        const double own = part.shift + part.s1 / part.elastic;
        norm += part.s2 - part.s1 * part.s1 / part.elastic + part.elastic * (own - mean) * (own - mean);
      }
    m.g_mean = mean;
    m.g_norm = std::max(norm, 0.0);
  } else {
    for (const Partial& part : partial)
      m.g_norm += part.s2;
  }
  return m;
}

}  // namespace contactbench::cg
