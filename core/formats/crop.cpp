#include "contactbench/core/formats/crop.hpp"

#include <cmath>
#include <string_view>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_tokens.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench {

std::optional<CropSpec> parse_crop(const std::string& text) {
  if (text == "measured") return CropSpec{CropSpec::Kind::measured};
  CropSpec crop;
  std::string_view numbers;
  if (text.starts_with("px:")) {
    crop.kind = CropSpec::Kind::pixels;
    numbers = std::string_view(text).substr(3);
  } else if (text.starts_with("m:")) {
    crop.kind = CropSpec::Kind::metres;
    numbers = std::string_view(text).substr(2);
  } else {
    return std::nullopt;
  }
  const std::vector<std::string_view> parts = formats::split_tokens(numbers, [](char c) { return c == ','; });
  if (parts.size() != 4) return std::nullopt;
  Real values[4];
  for (int k = 0; k < 4; ++k) {
    const std::optional<Real> value =
        formats::parse_real(formats::trim(parts[static_cast<std::size_t>(k)], formats::is_blank));
    if (!value || !std::isfinite(*value) || *value < 0) return std::nullopt;
    values[k] = *value;
  }
  if (crop.kind == CropSpec::Kind::pixels)
    for (const Real v : values)
      if (v != std::floor(v)) return std::nullopt;
  if (!(values[2] > 0) || !(values[3] > 0)) return std::nullopt;
  crop.x0 = values[0];
  crop.y0 = values[1];
  crop.width = values[2];
  crop.height = values[3];
  return crop;
}

std::string to_string(const CropSpec& crop) {
  if (crop.kind == CropSpec::Kind::measured) return "measured";
  // Shortest decimals that read back to the same doubles: a resolved scene re-reads the same region.
  return std::string(crop.kind == CropSpec::Kind::pixels ? "px:" : "m:") + formats::format_real(crop.x0) +
         "," + formats::format_real(crop.y0) + "," + formats::format_real(crop.width) + "," +
         formats::format_real(crop.height);
}

namespace formats {

namespace {

// The largest all-valid rectangle, by the maximal rectangle in a histogram row by row (each column's run of
// valid points ending at the row; a stack of increasing runs): O(nx ny).
struct Rectangle {
  Index x0 = 0, y0 = 0, nx = 0, ny = 0;
};

Rectangle largest_measured(const std::vector<Real>& values, Index nx, Index ny) {
  std::vector<Index> run(static_cast<std::size_t>(nx), 0);
  std::vector<Index> stack;
  Rectangle best;
  for (Index y = 0; y < ny; ++y) {
    for (Index x = 0; x < nx; ++x)
      run[static_cast<std::size_t>(x)] =
          std::isnan(values[static_cast<std::size_t>(y * nx + x)]) ? 0 : run[static_cast<std::size_t>(x)] + 1;
    stack.clear();
    for (Index x = 0; x <= nx; ++x) {
      const Index height = x < nx ? run[static_cast<std::size_t>(x)] : 0;
      while (!stack.empty() && run[static_cast<std::size_t>(stack.back())] >= height) {
        const Index h = run[static_cast<std::size_t>(stack.back())];
        stack.pop_back();
        const Index left = stack.empty() ? 0 : stack.back() + 1;
        const Index width = x - left;
        if (h * width > best.nx * best.ny) best = Rectangle{left, y - h + 1, width, h};
      }
      stack.push_back(x);
    }
  }
  return best;
}

}  // namespace

CropResult crop_values(const std::filesystem::path& path, std::vector<Real>& values, Index& nx, Index& ny,
                       Real& lx, Real& ly, const CropSpec& crop) {
  const Real dx = lx / static_cast<Real>(nx), dy = ly / static_cast<Real>(ny);
  Rectangle r;
  if (crop.kind == CropSpec::Kind::measured) {
    r = largest_measured(values, nx, ny);
    if (r.nx * r.ny == 0) throw InputError(path, 0, "crop = measured: no point of the grid is measured");
  } else if (crop.kind == CropSpec::Kind::pixels) {
    r = Rectangle{static_cast<Index>(crop.x0), static_cast<Index>(crop.y0), static_cast<Index>(crop.width),
                  static_cast<Index>(crop.height)};
  } else {
    // The points whose positions ix dx lie in [x0, x0 + width) (a relative 1e-9 of a step of slack for the
    // rounding of the given numbers).
    const auto first = [](Real start, Real step) {
      return static_cast<Index>(std::ceil(start / step - 1e-9));
    };
    const auto end = [](Real stop, Real step) { return static_cast<Index>(std::ceil(stop / step - 1e-9)); };
    r.x0 = first(crop.x0, dx);
    r.y0 = first(crop.y0, dy);
    r.nx = end(crop.x0 + crop.width, dx) - r.x0;
    r.ny = end(crop.y0 + crop.height, dy) - r.y0;
  }
  if (r.nx < 1 || r.ny < 1 || r.x0 < 0 || r.y0 < 0 || r.x0 + r.nx > nx || r.y0 + r.ny > ny)
    throw InputError(path, 0,
                     "crop " + to_string(crop) + " selects columns " + std::to_string(r.x0) + " to " +
                         std::to_string(r.x0 + r.nx - 1) + " and rows " + std::to_string(r.y0) + " to " +
                         std::to_string(r.y0 + r.ny - 1) + ", not a non-empty part of the file's " +
                         std::to_string(nx) + " x " + std::to_string(ny) + " grid");
  std::vector<Real> kept(static_cast<std::size_t>(r.nx * r.ny));
  for (Index y = 0; y < r.ny; ++y)
    for (Index x = 0; x < r.nx; ++x)
      kept[static_cast<std::size_t>(y * r.nx + x)] =
          values[static_cast<std::size_t>((r.y0 + y) * nx + r.x0 + x)];
  values = std::move(kept);
  nx = r.nx;
  ny = r.ny;
  lx = dx * static_cast<Real>(nx);
  ly = dy * static_cast<Real>(ny);
  return CropResult{r.x0, r.y0};
}

}  // namespace formats
}  // namespace contactbench
