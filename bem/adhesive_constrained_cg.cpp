#include "contactbench/bem/adhesive_constrained_cg.hpp"

#include <cmath>

#include "contactbench/bem/half_space.hpp"

namespace contactbench {

namespace {

// A point whose side the iteration changed this often is left where it is for the rest of the CG (the
// zone's edge crosses it); the fixed point that follows decides it with its own rule.
constexpr unsigned char kFlipsToFreeze = 3;

}  // namespace

ConstrainedCgOutcome solve_dugdale_constrained_cg(HalfSpace& half_space, const HeightMap& heights,
                                                  const AdhesionLaw& law, bool load, Real value,
                                                  Real tolerance, Index max_iterations, HeightMap& pressure,
                                                  HeightMap& attraction) {
  ConstrainedCgOutcome outcome;
  const Index n = heights.size();
  const Real sigma0 = law.stress, reach = law.reach();
  HeightMap traction(heights.rows(), heights.cols()), base(heights.rows(), heights.cols());
  HeightMap direction = HeightMap::Zero(heights.rows(), heights.cols());
  HeightMap response(heights.rows(), heights.cols());
  std::vector<unsigned char> flips(static_cast<std::size_t>(n), 0);
  // A pixel's displacement under a unit pressure on itself [m/Pa]: the first step into contact when nothing
  // touches yet (separation control from no contact), p = -g / G_self.
  HeightMap unit = HeightMap::Zero(heights.rows(), heights.cols());
  unit(0, 0) = 1;
  half_space.apply(unit, response);
  const Real self_response = response(0, 0);
  const Real half_own_pull = self_response * sigma0 / 2;
  Real last_norm = 1;
  bool conjugate = false;
  for (Index k = 0; k < max_iterations; ++k) {
    // Load control: the repulsive load carries the net load and the pull of the zone (P + mean(a)).
    if (load) {
      const Real repulsive = value + attraction.mean();
      if (!(repulsive > 0))
        return outcome;  // no contact holds this load with this zone: the fixed point says
      const Real mean = pressure.mean();
      if (mean > 0)
        pressure *= repulsive / mean;
      else
        pressure.setConstant(repulsive);
    }
    ++outcome.iterations;
    traction = pressure - attraction;
    half_space.apply(traction, base);
    base -= heights;  // gap = d + base, g = d - h + G t (adhesive_solver.hpp)
    // The flat's height: load control, where the mean gap over the contact set is zero (Polonsky–Keer).
    Real d = value;
    Index contact = 0;
    if (load) {
      Real sum = 0;
      for (Index i = 0; i < n; ++i)
        if (pressure.data()[i] > 0) {
          sum += base.data()[i];
          ++contact;
        }
      d = contact > 0 ? -sum / static_cast<Real>(contact) : -base.maxCoeff();
    }
    // The gap's residual on the contact set and the conjugate direction (Polonsky and Keer eq. 11-13).
    Real norm = 0;
    for (Index i = 0; i < n; ++i)
      if (pressure.data()[i] > 0) norm += std::pow(base.data()[i] + d, 2);
    const Real beta = conjugate ? norm / last_norm : 0;
    for (Index i = 0; i < n; ++i)
      direction.data()[i] = pressure.data()[i] > 0 ? base.data()[i] + d + beta * direction.data()[i] : 0;
    last_norm = norm > 0 ? norm : 1;
    half_space.apply(direction, response);
    Real response_mean = 0;
    if (load && contact > 0) {
      for (Index i = 0; i < n; ++i)
        if (pressure.data()[i] > 0) response_mean += response.data()[i];
      response_mean /= static_cast<Real>(contact);
    }
    Real numerator = 0, denominator = 0;
    for (Index i = 0; i < n; ++i)
      if (pressure.data()[i] > 0) {
        numerator += (base.data()[i] + d) * direction.data()[i];
        denominator += (response.data()[i] - response_mean) * direction.data()[i];
      }
    const Real step = denominator > 0 ? numerator / denominator : 1 / self_response;
    // The step, projected on p >= 0; points out of contact that overlap enter (Polonsky and Keer eq. 15).
    Real change = 0, size = 0;
    bool entered = false;
    Index moved = 0;
    for (Index i = 0; i < n; ++i) {
      Real& p = pressure.data()[i];
      const Real gap = base.data()[i] + d;
      const Real old = p;
      if (p > 0) {
        p = std::max<Real>(p - step * direction.data()[i], 0);
      } else if (gap < 0) {
        p = -step * gap;
        if (p < 0) p = 0;
        entered = entered || p > 0;
      }
      change += std::abs(p - old);
      size += p;
      // The cohesive zone from the current gap: in contact or closer than δc.
      unsigned char& flipped = flips[static_cast<std::size_t>(i)];
      if (flipped >= kFlipsToFreeze) continue;
      // The fixed point's rule (adhesive_solver.cpp): the gap with half of the point's own pull below δc,
      // the same test whichever side the point is on now.
      const Real own = attraction.data()[i] > 0 ? half_own_pull : -half_own_pull;
      const Real a = (p > 0 || gap + own < reach) ? sigma0 : 0;
      if (a != attraction.data()[i]) {
        attraction.data()[i] = a;
        ++flipped;
        ++moved;
      }
    }
    conjugate = !entered && moved == 0;
    if (moved == 0 && change <= tolerance * std::max<Real>(size, 1e-300)) {
      outcome.settled = true;
      return outcome;
    }
  }
  return outcome;
}

}  // namespace contactbench
