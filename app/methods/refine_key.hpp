// The `refine` key, shared by every method that can work on the scene's surface Fourier-refined to more
// points a side (bem, plateau, plateau_hertz; docs/theory.md section 2, "sampling one surface more
// finely"): the same key, range and messages wherever it appears.
#pragma once

#include "contactbench/app/methods/method.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// refine = 0 (the surface as it is) or a count of points a side in [points of the surface, kMaxPointsASide];
// `fallback` when the key is absent.
Index read_refine_key(const Section& keys, const SceneContext& context, Index fallback);

// Once the surface is made: refinement needs a periodic surface and at least its own points a side.
void check_refine_key(const MethodCheck& check, Index refine);

}  // namespace contactbench
