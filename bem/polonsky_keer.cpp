#include "bem/polonsky_keer.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>

#include "core/error.hpp"

namespace contactbench {

namespace {
// Concrete, not an expression: the contact set must not follow the pressure when it changes.
using BoolMap = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
}  // namespace

PolonskyKeer::PolonskyKeer(const Surface& surface, Real modulus, PolonskyKeerOptions options, int threads)
    : surface_(surface.centred()),
      options_(options),
      half_space_(make_half_space(surface.grid(), modulus, threads)) {
  if (!(options_.tolerance > 0) || options_.max_iterations < 1)
    throw Error("Polonsky-Keer: tolerance must be > 0 and max_iterations >= 1");
}

PolonskyKeer::~PolonskyKeer() = default;

const ContactSolution& PolonskyKeer::solve(Real mean_pressure) {
  if (!(std::isfinite(mean_pressure) && mean_pressure >= 0))
    throw Error("Polonsky-Keer: the mean pressure must be finite and >= 0 Pa, got " +
                std::to_string(mean_pressure));
  const auto start = std::chrono::steady_clock::now();
  const HeightMap& h = surface_.heights();
  if (mean_pressure == 0) {
    // No load, no contact: the flat rests at the highest point, touching nothing (the set {h > d} is empty).
    solution_ = ContactSolution{};
    solution_.pressure = HeightMap::Zero(h.rows(), h.cols());
    solution_.separation = h.maxCoeff();
    solution_.gap = solution_.separation - h;
    solution_.converged = true;
    warm_ = false;  // nothing to start the next load from
    solution_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return solution_;
  }
  const Index n = h.size();
  const Real total = mean_pressure * static_cast<Real>(n);  // sum of p over the nodes (pixel areas equal)
  const Real height_range = h.maxCoeff() - h.minCoeff();

  HeightMap& p = solution_.pressure;
  if (!warm_) {
    p = HeightMap::Constant(h.rows(), h.cols(), mean_pressure);  // cold start: uniform, the exact load
  } else {
    p *= total / p.sum();  // warm start: the previous pressure scaled to the new load
  }
  HeightMap u, g(h.rows(), h.cols()), t = HeightMap::Zero(h.rows(), h.cols()), r;
  Real g_norm_old = 1, delta = 0, change = 0;  // delta = 0: the first step is steepest descent
  Index iteration = 0;
  bool converged = false;
  for (; iteration < options_.max_iterations; ++iteration) {
    // Gap up to the unknown flat height, made zero-mean on the contact set (which fixes the flat).
    half_space_->apply(p, u);
    g = u - h;
    const BoolMap in_contact = p > 0;
    const Index contact = in_contact.count();
    if (contact == 0) throw Error("Polonsky-Keer: the contact set became empty");
    const Real g_mean = in_contact.select(g, 0).sum() / static_cast<Real>(contact);
    g -= g_mean;
    const Real g_norm = in_contact.select(g.square(), 0).sum();
    // Conjugate direction on the contact set (PK eq. 11), restarted after the set grew (delta = 0).
    t = in_contact.select(g + (delta * g_norm / g_norm_old) * t, 0);
    g_norm_old = g_norm;
    half_space_->apply(t, r);
    const Real r_mean = in_contact.select(r, 0).sum() / static_cast<Real>(contact);
    r -= r_mean;
    const Real tr = in_contact.select(t * r, 0).sum();
    if (!(tr > 0)) {  // no descent left: the gap is already zero on the contact set
      converged = true;
      break;
    }
    const Real tau = in_contact.select(g * t, 0).sum() / tr;
    const HeightMap p_old = p;
    p = (p - tau * t).max(0);
    // Points outside the contact set that the surface penetrates (negative gap) re-enter it (PK eq. 14).
    const BoolMap overlap = (p == 0) && (g < 0) && !in_contact;
    const bool any_overlap = overlap.any();
    p = overlap.select(p - tau * g, p);
    delta = any_overlap ? 0 : 1;
    p *= total / p.sum();  // the prescribed load
    change = (p - p_old).abs().sum() / p.sum();
    if (change < options_.tolerance) {
      converged = true;
      ++iteration;
      break;
    }
  }

  // The solution: gap with the flat's height from the contact set, and the residual of complementarity.
  half_space_->apply(p, u);
  const BoolMap in_contact = p > 0;
  const Index contact = in_contact.count();
  const Real separation = in_contact.select(h - u, 0).sum() / static_cast<Real>(contact);
  g = separation - h + u;
  solution_.gap = in_contact.select(HeightMap::Zero(h.rows(), h.cols()), g);
  solution_.mean_pressure = mean_pressure;
  solution_.separation = separation;
  solution_.contact_points = contact;
  solution_.iterations = iteration;
  solution_.change = change;
  // Relative to the height range (to 1 m for a flat surface, whose range is 0).
  solution_.residual = in_contact.select(g.abs(), 0).maxCoeff() / (height_range > 0 ? height_range : 1.0);
  solution_.converged = converged;
  solution_.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!converged)
    std::cerr << "contactbench: WARNING: Polonsky-Keer did not converge at P/A0 = " << mean_pressure
              << " Pa in " << iteration << " iterations (relative pressure change " << change
              << " > tolerance " << options_.tolerance << "); the result is marked converged = false\n";
  warm_ = true;
  return solution_;
}

}  // namespace contactbench
