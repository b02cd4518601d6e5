// Row (scan-line) alignment (docs/formats.md "regions and levelling"): a scanning instrument measures line by
// line, and each line may carry its own offset (or tilt) from drift; subtracting each row's mean, median or
// least-squares line removes it. It runs after filling and before the polynomial levelling.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

enum class RowAlignment {
  none,
  mean,    // each row's mean
  median,  // each row's median (robust to a few spikes)
  linear,  // each row's least-squares line a + b x
};

std::string_view to_string(RowAlignment alignment);
std::optional<RowAlignment> parse_row_alignment(std::string_view text);
// The names parse_row_alignment accepts (the command line, scenes and Python check against them).
const std::vector<std::string_view>& row_alignment_names();

// Rows are along x (heights(iy, ix)): each row loses its own mean, median or line.
void align_rows(HeightMap& heights, RowAlignment alignment);

}  // namespace contactbench
