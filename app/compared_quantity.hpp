// What a scene compares (`compare = ["area", "mean_gap", "stiffness"]`, scenes/README.md): the real contact
// area, the mean gap and the contact stiffness per unit area, each against load (docs/theory.md section 12).
// The area is always compared; the others only when the scene names them, so that a scene comparing only
// the area runs exactly what it ran before (no stiffness solve, no spectrum for Persson's gap).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace contactbench {

enum class Quantity {
  area,       // A/A0
  mean_gap,   // u-bar [m]: the mean of the gap field over the nominal area
  stiffness,  // K = -dP/dd per unit area [Pa/m], d the rigid approach of the flat (docs/theory.md 12.1)
};

std::string_view quantity_name(Quantity quantity);  // "area", "mean_gap", "stiffness"
std::string_view quantity_unit(Quantity quantity);  // "A/A0", "m", "Pa/m"
std::optional<Quantity> quantity_of(std::string_view name);
std::vector<Quantity> known_quantities();
std::string quantities_text();  // "\"area\", \"mean_gap\", \"stiffness\""

}  // namespace contactbench
