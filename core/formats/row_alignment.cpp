#include "contactbench/core/formats/row_alignment.hpp"

#include <algorithm>
#include <vector>

namespace contactbench {

std::string_view to_string(RowAlignment alignment) {
  switch (alignment) {
    case RowAlignment::none:
      return "none";
    case RowAlignment::mean:
      return "mean";
    case RowAlignment::median:
      return "median";
    case RowAlignment::linear:
      return "linear";
  }
  return "unknown";
}

const std::vector<std::string_view>& row_alignment_names() {
  static const std::vector<std::string_view> names{
      to_string(RowAlignment::none), to_string(RowAlignment::mean), to_string(RowAlignment::median),
      to_string(RowAlignment::linear)};
  return names;
}

std::optional<RowAlignment> parse_row_alignment(std::string_view text) {
  for (const RowAlignment a :
       {RowAlignment::none, RowAlignment::mean, RowAlignment::median, RowAlignment::linear})
    if (text == to_string(a)) return a;
  return std::nullopt;
}

void align_rows(HeightMap& heights, RowAlignment alignment) {
  if (alignment == RowAlignment::none) return;
  const Index nx = heights.cols();
  std::vector<Real> row(static_cast<std::size_t>(nx));
  const Real centre = (static_cast<Real>(nx) - 1) / 2;
  Real xx = 0;  // sum of the centred positions' squares, the same for every row
  for (Index x = 0; x < nx; ++x)
    xx += (static_cast<Real>(x) - centre) * (static_cast<Real>(x) - centre);
  for (Index y = 0; y < heights.rows(); ++y) {
    if (alignment == RowAlignment::median) {
      for (Index x = 0; x < nx; ++x)
        row[static_cast<std::size_t>(x)] = heights(y, x);
      const auto middle = row.begin() + nx / 2;
      std::nth_element(row.begin(), middle, row.end());
      Real median = *middle;
      if (nx % 2 == 0) median = (median + *std::max_element(row.begin(), middle)) / 2;
      heights.row(y).array() -= median;
      continue;
    }
    const Real mean = heights.row(y).mean();
    Real slope = 0;
    if (alignment == RowAlignment::linear && xx > 0) {
      Real xh = 0;
      for (Index x = 0; x < nx; ++x)
        xh += (static_cast<Real>(x) - centre) * heights(y, x);
      slope = xh / xx;
    }
    for (Index x = 0; x < nx; ++x)
      heights(y, x) -= mean + slope * (static_cast<Real>(x) - centre);
  }
}

}  // namespace contactbench
