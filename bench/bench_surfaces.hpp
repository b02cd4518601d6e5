// Surfaces and binary maps the benchmarks share: made by the project's own generator, seeded, cached.
#pragma once

#include "core/labelling.hpp"
#include "core/surface.hpp"

namespace contactbench::bench {

// Threads every benchmark runs on (the project's target machine has two cores).
inline constexpr int kThreads = 2;

// The paper's surface A spectrum (sigma 0.5 um, H 0.5, qr 3.14e4 1/m) on n x n points over 200 um, qs at
// the Nyquist wavevector of that grid: roughness down to the pixel, the hard case for labelling.
const Surface& rough_surface(Index n);

// {h > z} of rough_surface(n) with z chosen so that `coverage` (a fraction) of the points lie above.
const BinaryMap& contact_map(Index n, double coverage);

}  // namespace contactbench::bench
