// The magnitudes the spectral moments and the boundary-element solvers are trusted with. Both sum squares
// (of heights, slopes, pressures) over up to 2^30 points; double precision holds about 1e-308 to 1e308, so
// a quantity whose square must stay inside that range, with room for the point count and the wavevectors'
// powers, lies within 1e-100 to 1e100 of its SI unit. Outside it a sum overflows to infinity or underflows
// to zero, and the result is silently wrong (moments reported as null, a solve "converged" with the whole
// grid in contact): such inputs are refused, naming the quantity.
#pragma once

#include <string>

#include "contactbench/core/types.hpp"

namespace contactbench {

inline constexpr Real kSmallestMagnitude = 1e-100;
inline constexpr Real kLargestMagnitude = 1e100;

// |value| within [kSmallestMagnitude, kLargestMagnitude]; zero counts as within (a flat surface, no load).
bool within_magnitudes(Real value);

// "the heights' range 3e+290 m lies outside 1e-100 to 1e100 m, where sums of its squares stay within double
// precision": for messages.
std::string magnitude_problem(const std::string& what, Real value, const std::string& unit);

}  // namespace contactbench
