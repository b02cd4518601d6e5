#include "contactbench/core/profile_levelling.hpp"

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "contactbench/core/error.hpp"

namespace contactbench {

std::vector<Real> level_profile(std::span<const Real> x, std::span<const Real> h, Levelling levelling) {
  std::vector<Real> levelled(h.begin(), h.end());
  if (levelling == Levelling::none) return levelled;
  const int terms = levelling == Levelling::mean ? 1 : levelling == Levelling::plane ? 2 : 3;
  const auto n = static_cast<Eigen::Index>(x.size());
  if (x.size() != h.size() || n < terms + 1)
    throw Error("levelling a profile by a polynomial of " + std::to_string(terms) + " terms needs at least " +
                std::to_string(terms + 1) + " points");
  // Centred and scaled x keeps the normal equations well conditioned whatever the unit and offset of x.
  const Real centre = 0.5 * (x.front() + x.back()), half = 0.5 * (x.back() - x.front());
  Eigen::MatrixXd basis(n, terms);
  Eigen::VectorXd weights(n), heights(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    if (k + 1 < n && !(x[i + 1] > x[i])) throw Error("a profile's x must increase strictly");
    const Real left = k > 0 ? x[i] - x[i - 1] : 0, right = k + 1 < n ? x[i + 1] - x[i] : 0;
    weights(k) = std::sqrt(0.5 * (left + right));
    const Real s = (x[i] - centre) / half;
    for (int t = 0; t < terms; ++t)
      basis(k, t) = std::pow(s, t);
    heights(k) = h[i];
  }
  const Eigen::VectorXd fit =
      (weights.asDiagonal() * basis).colPivHouseholderQr().solve(weights.asDiagonal() * heights);
  const Eigen::VectorXd residual = heights - basis * fit;
  for (Eigen::Index k = 0; k < n; ++k)
    levelled[static_cast<std::size_t>(k)] = residual(k);
  return levelled;
}

}  // namespace contactbench
