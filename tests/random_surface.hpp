// The small periodic self-affine surface the plateau-model tests share: n x n points of 1 um, rms height
// 1 um, Hurst 0.8, roll-off at twice the lattice's smallest wavevector.
#pragma once

#include <cstdint>
#include <optional>

#include "contactbench/core/generation.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench::testing {

inline Surface random_surface(Index n, std::uint64_t seed) {
  constexpr Real um = 1e-6;
  const Grid grid{
      .nx = n, .ny = n, .lx = static_cast<Real>(n) * um, .ly = static_cast<Real>(n) * um, .periodic = true};
  const SelfAffinePsd psd{
      .sigma = 1 * um, .hurst = 0.8, .qr = 2 * grid.dqx(), .qs = std::nullopt, .anisotropy = 1};
  return generate_surface(grid, psd, seed);
}

}  // namespace contactbench::testing
