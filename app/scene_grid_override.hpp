// `contactbench run SCENE --grid N`: the same scene at another resolution, for a quick look (or a finer one).
// The generated surface is made on N points a side instead of surface.generate.grid, with the same size,
// spectrum and seed (the generator keys each mode's phase by its wavevector, so the modes both grids hold
// are the same; docs/theory.md section 2); every `refine` of the scene (surface.generate.refine and each
// method's) is scaled by N / grid, so that each method keeps its resolution relative to the surface. A qs the
// scene leaves at its default (the grid's Nyquist wavevector) follows the new grid; a qs it states is kept,
// and a grid that cannot carry it is refused with the least N that can. A surface read from a file has no
// grid to set: refused, naming surface.file (surface.crop runs part of a file). Docs: scenes/README.md.
#pragma once

#include <filesystem>

#include <toml++/toml.h>

#include "contactbench/app/scene.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// The scene's document with the grid set to `points` and its refine keys scaled; `as_written` is the same
// document already parsed (and so valid). Throws SceneError naming the key when the override cannot apply.
toml::table with_grid_override(const toml::table& document, const Scene& as_written, Index points,
                               const std::filesystem::path& origin);

}  // namespace contactbench
