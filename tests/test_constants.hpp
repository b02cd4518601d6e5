// Constants several test files share (one definition, so that files compiled together do not clash).
#pragma once

#include <filesystem>
#include <limits>

#include "contactbench/core/types.hpp"

namespace contactbench::testing {

// E* of the seed paper's material: E = 100 GPa, nu = 0.3 [Pa].
inline constexpr Real kPaperModulus = 1e11 / (1 - 0.3 * 0.3);
// A micrometre [m].
inline constexpr Real um = 1e-6;
// A quiet NaN (missing points of measured files).
inline constexpr Real nan = std::numeric_limits<Real>::quiet_NaN();
// The instrument files of data/formats/ (data/formats/README.md: provenance, reference values).
inline const std::filesystem::path kFormatSamples{CB_DATA_DIR "/formats"};

}  // namespace contactbench::testing
