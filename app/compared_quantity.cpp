#include "contactbench/app/compared_quantity.hpp"

namespace contactbench {

std::string_view quantity_name(Quantity quantity) {
  switch (quantity) {
    case Quantity::area:
      return "area";
    case Quantity::mean_gap:
      return "mean_gap";
    case Quantity::stiffness:
      return "stiffness";
  }
  return "";
}

std::string_view quantity_unit(Quantity quantity) {
  switch (quantity) {
    case Quantity::area:
      return "A/A0";
    case Quantity::mean_gap:
      return "m";
    case Quantity::stiffness:
      return "Pa/m";
  }
  return "";
}

std::vector<Quantity> known_quantities() {
  return {Quantity::area, Quantity::mean_gap, Quantity::stiffness};
}

std::optional<Quantity> quantity_of(std::string_view name) {
  for (const Quantity q : known_quantities())
    if (quantity_name(q) == name) return q;
  return std::nullopt;
}

std::string quantities_text() {
  std::string text;
  for (const Quantity q : known_quantities())
    text.append(text.empty() ? "" : ", ").append("\"").append(quantity_name(q)).append("\"");
  return text;
}

}  // namespace contactbench
