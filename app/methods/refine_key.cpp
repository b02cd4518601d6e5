#include "contactbench/app/methods/refine_key.hpp"

#include <string>

#include "contactbench/app/scene_toml.hpp"
#include "contactbench/app/section.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

Index read_refine_key(const Section& s, const SceneContext& context, Index fallback) {
  const std::int64_t low = context.surface_points.value_or(2);
  const auto refine =
      s.integer("refine", false,
                {[low](std::int64_t v) { return v == 0 || (v >= low && v <= kMaxPointsASide); },
                 "0 (the surface as is) or an integer in [" + std::to_string(low) + ", " +
                     std::to_string(kMaxPointsASide) + "]" +
                     (context.surface_points
                          ? " (the surface has " + std::to_string(*context.surface_points) + " points a side)"
                          : "")});
  return static_cast<Index>(refine.value_or(fallback));
}

void check_refine_key(const MethodCheck& check, Index refine) {
  const Grid& grid = check.surface.grid();
  if (refine > 0 && !grid.periodic)
    check.problem("refine",
                  "Fourier refinement needs a periodic surface, and this scene's surface is not periodic",
                  "refine = 0 (work on the file's own grid)");
  else if (refine > 0 && (refine < grid.nx || refine < grid.ny))
    check.problem("refine",
                  "out of range: got " + std::to_string(refine) + ", fewer points than the surface's " +
                      std::to_string(grid.nx) + " x " + std::to_string(grid.ny),
                  "0 or at least the surface's points a side");
}

}  // namespace contactbench
