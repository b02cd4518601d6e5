#include "contactbench/core/formats/height_unit.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/text_values.hpp"

namespace contactbench::formats {

namespace {

// Sq of the finite values about their mean; 0 for fewer than two.
Real rms_about_mean(std::span<const Real> values) {
  Real sum = 0;
  std::size_t count = 0;
  for (const Real v : values)
    if (std::isfinite(v)) sum += v, ++count;
  if (count < 2) return 0;
  const Real mean = sum / static_cast<Real>(count);
  Real squares = 0;
  for (const Real v : values)
    if (std::isfinite(v)) squares += (v - mean) * (v - mean);
  return std::sqrt(squares / static_cast<Real>(count));
}

std::string short_number(Real value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

}  // namespace

Real given_units_per_metre(const std::filesystem::path& path, const std::string& unit) {
  if (unit == "m") return 1;
  if (unit == "mm") return 1e3;
  if (unit == "um" || unit == "\u00b5m" || unit == "\u03bcm") return 1e6;
  if (unit == "nm") return 1e9;
  if (unit == "pm") return 1e12;
  throw InputError(path, 0,
                   "unknown height unit " + formats::quoted(unit) +
                       " (--unit, unit = \"...\"); accepted: " + std::string(accepted_length_units) + ", pm");
}

void check_plausible_as_metres(const std::filesystem::path& path, std::span<const Real> heights,
                               const std::string& kind) {
  const Real sq = rms_about_mean(heights);
  if (sq == 0 || (sq >= kLeastPlausibleSq && sq <= kGreatestPlausibleSq)) return;
  // The units in which this Sq would be a plausible roughness, coarsest first.
  constexpr std::array<std::pair<const char*, Real>, 3> smaller = {
      {{"mm", 1e-3}, {"um", 1e-6}, {"nm", 1e-9}}};
  std::string likely;
  if (sq > kGreatestPlausibleSq) {
    for (const auto& [name, metres] : smaller) {
      const Real scaled = sq * metres;
      if (scaled < kLeastPlausibleSq || scaled > kGreatestPlausibleSq) continue;
      likely +=
          std::string(likely.empty() ? "" : " or ") + name + " (Sq " + short_number(sq) + " " + name + ")";
    }
  }
  throw InputError(
      path, 0,
      "a " + kind + " states no unit and its heights taken as metres have Sq " + short_number(sq) +
          " m, outside the plausible 1 pm to 1 mm; " +
          (likely.empty() ? std::string("if they really are metres") : "the numbers are likely " + likely) +
          ": name the unit with --unit (unit = \"...\" in a scene's [surface]; accepted: " +
          std::string(accepted_length_units) + ", pm)");
}

}  // namespace contactbench::formats
