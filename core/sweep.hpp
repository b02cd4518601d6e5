// The geometric sweep: bearing area A_c(z) and spot count N(z) of {h > z} for many levels in one pass
// (docs/theory.md section 3): points are visited in descending height and merged in a union-find, so the
// components after each level are known without labelling any level. With several threads the grid is cut
// into horizontal stripes swept independently, and the spots counted twice along the seams are removed
// exactly afterwards; the result does not depend on the thread count.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include <string>
#include <vector>

#include "contactbench/core/surface.hpp"
#include "contactbench/core/topology.hpp"

namespace contactbench {

// Which levels z the sweep reports.
struct SweepLevels {
  enum class Kind {
    exact,    // every distinct height, descending: A_c N is constant between two of them
    uniform,  // count + 1 levels from the highest height down to the lowest, equally spaced
    paper,    // the paper's: count + 1 levels from the highest height h_max down to the mean plane,
              // in steps of h_max / count (count = 500 gives its steps of 0.002 h_max)
  };
  Kind kind = Kind::exact;
  Index count = 500;

  static SweepLevels exact() { return {Kind::exact, 0}; }
  static SweepLevels uniform(Index count) { return {Kind::uniform, count}; }
  static SweepLevels paper(Index count = 500) { return {Kind::paper, count}; }

  // The levels a scene, the command line and Python accept, declared once: a name ("exact", "paper") or a
  // count >= 1 of uniform steps; nullopt for anything else (the caller names its key with kAccepted).
  static std::optional<SweepLevels> named(std::string_view name);
  static std::optional<SweepLevels> counted(std::int64_t count);
  static constexpr std::string_view kAccepted = "\"exact\", \"paper\" or an integer count >= 1";
};

// The connectivities of a contact spot (4 or 8 neighbours), as accepted everywhere; nullopt for any other.
std::optional<Connectivity> connectivity_of(std::int64_t neighbours);
inline constexpr std::string_view kConnectivityAccepted = "4, 8";

// A_c(z) and N(z) at descending levels z[0] > z[1] > ...; row j describes {h > z[j]} (strictly above).
// The first level is the highest height, where nothing is above: area 0, no spot.
struct SweepCurve {
  std::vector<Real> z;              // level [m], descending
  std::vector<Real> area_fraction;  // A_c(z) / A0
  std::vector<Index> points;        // points with h > z (area_fraction = points / (nx ny))
  std::vector<Index> spots;         // N(z): connected components of {h > z}
  Topology topology;
  SweepLevels levels;
  Real nominal_area = 0;  // A0 = lx ly [m^2]
};

// Topology::for_surface(connectivity, surface.grid().periodic) is what a surface's own periodicity implies.
// For fixed levels on a surface of constant height the levels coincide (all at that height).
// Checks first (check_fits_in_memory) that the sweep's work and output fit: see sweep_memory_bytes.
SweepCurve sweep(const Surface& surface, const SweepLevels& levels, const Topology& topology,
                 int threads = 1);

// The peak memory of sweep() beyond the heights themselves [bytes], estimated from its parameters: per point
// the union-find forest (8 B) and, for exact levels, the sorted order (16 B), a record (24 B) and an output
// row (32 B) per distinct height; for fixed levels the level index (4 B) per point and, per level, the level
// (8 B), one count, one record per stripe (32 B each) and an output row (32 B). Saturates rather than wraps.
std::uintmax_t sweep_memory_bytes(Index points, const SweepLevels& levels, int threads);

}  // namespace contactbench
