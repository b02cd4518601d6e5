#include "contactbench/core/formats/surface_repair.hpp"

#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/harmonic_fill.hpp"

namespace contactbench {

std::string_view to_string(FillMethod method) {
  switch (method) {
    case FillMethod::none:
      return "none";
    case FillMethod::harmonic:
      return "harmonic";
    case FillMethod::mean:
      return "mean";
  }
  return "unknown";
}

std::string_view to_string(Levelling levelling) {
  switch (levelling) {
    case Levelling::none:
      return "none";
    case Levelling::mean:
      return "mean";
    case Levelling::plane:
      return "plane";
    case Levelling::quadratic:
      return "quadratic";
  }
  return "unknown";
}

const std::vector<std::string_view>& fill_method_names() {
  static const std::vector<std::string_view> names{
      to_string(FillMethod::none), to_string(FillMethod::harmonic), to_string(FillMethod::mean)};
  return names;
}

const std::vector<std::string_view>& levelling_names() {
  static const std::vector<std::string_view> names{to_string(Levelling::none), to_string(Levelling::mean),
                                                   to_string(Levelling::plane),
                                                   to_string(Levelling::quadratic)};
  return names;
}

std::optional<FillMethod> parse_fill_method(std::string_view text) {
  if (text == "none") return FillMethod::none;
  if (text == "harmonic") return FillMethod::harmonic;
  if (text == "mean") return FillMethod::mean;
  return std::nullopt;
}

std::optional<Levelling> parse_levelling(std::string_view text) {
  if (text == "none") return Levelling::none;
  if (text == "mean") return Levelling::mean;
  if (text == "plane") return Levelling::plane;
  if (text == "quadratic") return Levelling::quadratic;
  return std::nullopt;
}

void fill_invalid_points(std::vector<Real>& values, Index nx, Index ny, FillMethod method) {
  Index unknowns = 0;
  Real valid_sum = 0;
  for (const Real value : values) {
    if (std::isnan(value)) {
      ++unknowns;
    } else {
      valid_sum += value;
    }
  }
  if (unknowns == 0) return;
  if (method == FillMethod::none)
    throw Error(std::to_string(unknowns) + " invalid points and no fill method");
  if (unknowns == static_cast<Index>(values.size()))
    throw Error("every point is invalid: there is nothing to fill from");
  if (method == FillMethod::mean) {
    const Real mean = valid_sum / static_cast<Real>(values.size() - static_cast<std::size_t>(unknowns));
    for (Real& value : values)
      if (std::isnan(value)) value = mean;
    return;
  }
  if (unknowns > kMaxHarmonicFillPoints)
    throw Error("harmonic fill of " + std::to_string(unknowns) + " invalid points refused: more than the " +
                std::to_string(kMaxHarmonicFillPoints) +
                " it fills in a few seconds; read the measured part (--crop measured, crop = "
                "\"measured\"), or fill with the mean (--fill mean)");
  fill_harmonic(values, nx, ny);
}

namespace {

// The least-squares a + b u + c v + d u^2 + e u v + f v^2 with u, v the positions scaled to [-1, 1] (so that
// the 6 x 6 normal equations are well conditioned; the fit does not depend on the scaling), subtracted.
void subtract_quadratic(HeightMap& heights) {
  const Index ny = heights.rows(), nx = heights.cols();
  const auto scaled = [](Index k, Index n) {
    return n > 1 ? 2 * static_cast<Real>(k) / static_cast<Real>(n - 1) - 1 : Real{0};
  };
  Eigen::Matrix<Real, 6, 6> normal = Eigen::Matrix<Real, 6, 6>::Zero();
  Eigen::Matrix<Real, 6, 1> right = Eigen::Matrix<Real, 6, 1>::Zero();
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      const Real u = scaled(x, nx), v = scaled(y, ny);
      const Eigen::Matrix<Real, 6, 1> basis{{1, u, v, u * u, u * v, v * v}};
      normal.noalias() += basis * basis.transpose();
      right.noalias() += basis * heights(y, x);
    }
  // Fewer than three rows or columns leave some terms undetermined; the pseudo-inverse fits those as zero.
  const Eigen::Matrix<Real, 6, 1> c = normal.completeOrthogonalDecomposition().solve(right);
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      const Real u = scaled(x, nx), v = scaled(y, ny);
      heights(y, x) -= c(0) + c(1) * u + c(2) * v + c(3) * u * u + c(4) * u * v + c(5) * v * v;
    }
}

}  // namespace

void level_heights(HeightMap& heights, const Grid& grid, Levelling levelling) {
  if (levelling == Levelling::none) return;
  const Real mean = heights.mean();
  if (levelling == Levelling::mean) {
    heights -= mean;
    return;
  }
  if (levelling == Levelling::quadratic) return subtract_quadratic(heights);
  // On a full grid the centred coordinates are orthogonal to each other and to the constant, so the normal
  // equations of the least-squares plane decouple: slope_x = sum(xc h) / sum(xc^2), and the same along y.
  const Index nx = grid.nx;
  const Index ny = grid.ny;
  const Real x_centre = (static_cast<Real>(nx) - 1) / 2;
  const Real y_centre = (static_cast<Real>(ny) - 1) / 2;
  Real xh = 0, yh = 0, xx = 0, yy = 0;
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x) {
      const Real xc = static_cast<Real>(x) - x_centre;
      const Real yc = static_cast<Real>(y) - y_centre;
      xh += xc * heights(y, x);
      yh += yc * heights(y, x);
      xx += xc * xc;
      yy += yc * yc;
    }
  const Real slope_x = xx > 0 ? xh / xx : 0;  // per grid step
  const Real slope_y = yy > 0 ? yh / yy : 0;
  for (Index y = 0; y < ny; ++y)
    for (Index x = 0; x < nx; ++x)
      heights(y, x) -=
          mean + slope_x * (static_cast<Real>(x) - x_centre) + slope_y * (static_cast<Real>(y) - y_centre);
}

}  // namespace contactbench
