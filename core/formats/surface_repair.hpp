// What a measured topography needs before it is a surface to compute on (docs/formats.md "invalid points"
// and "levelling"): its unmeasured points filled, its tilt removed.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// How invalid (unmeasured) points become heights. none: refuse a file that has any.
enum class FillMethod {
  none,
  harmonic,  // Laplace interpolation: each filled height is the mean of its four neighbours, valid ones fixed
  mean,      // the mean of the valid heights
};

// What is subtracted from the heights after reading. none: the heights as stored.
enum class Levelling {
  none,
  mean,       // the mean height
  plane,      // the least-squares plane a + b x + c y over all points (polynomial of degree 1)
  quadratic,  // the least-squares polynomial of degree 2 (also x^2, x y, y^2: curvature, a spherical form)
};

std::string_view to_string(FillMethod method);
std::string_view to_string(Levelling levelling);
// Parse "none" | "harmonic" | "mean" (and "none" | "mean" | "plane" | "quadratic"); nullopt for anything
// else.
std::optional<FillMethod> parse_fill_method(std::string_view text);
std::optional<Levelling> parse_levelling(std::string_view text);
// The names each parse accepts, in the order a message lists them: the one declaration the command line,
// scenes and Python check against.
const std::vector<std::string_view>& fill_method_names();
const std::vector<std::string_view>& levelling_names();

// The most invalid points the harmonic fill takes (core/formats/harmonic_fill.hpp): its cost grows like the
// count (docs/formats.md: 1 to 2 s per million points and about 200 bytes a point), so this bound (a 2048^2
// grid all but unmeasured: about 6 s, under 1 GB) keeps a fill from running unseen for minutes; more are
// refused, with the ways out.
inline constexpr Index kMaxHarmonicFillPoints = Index{1} << 22;

// Replaces every NaN of `values` (ny x nx, row-major) by the method's height. Throws Error when no value is
// valid (nothing to fill from), when `method` is none and there is a NaN, or when a harmonic fill has more
// than kMaxHarmonicFillPoints to fill.
void fill_invalid_points(std::vector<Real>& values, Index nx, Index ny, FillMethod method);

// Subtracts the mean, the least-squares plane or quadratic in place (heights(iy, ix) at x = ix dx, y = iy
// dy).
void level_heights(HeightMap& heights, const Grid& grid, Levelling levelling);

}  // namespace contactbench
