// The [surface] and [material] of the small scenes the pipeline tests run: the paper's surface A on 32 x 32
// points over 200 um (seed 2), E = 100 GPa, nu = 0.3. Tests append their [loads] and [methods].
#pragma once

#include <string>

namespace contactbench {

inline const std::string kSmallSurfaceAndMaterial = R"(
[surface]
generate = { sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, size = 200e-6, grid = 32, seed = 2 }
[material]
E = 100e9
nu = 0.3
)";

}  // namespace contactbench
