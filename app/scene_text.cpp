#include "contactbench/app/scene_text.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace contactbench {

std::string exact_number(Real value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string join(const std::vector<std::string>& items) {
  std::string text;
  for (const auto& item : items)
    text.append(text.empty() ? "" : ", ").append(item);
  return text;
}

bool portable_name(std::string_view name, bool allow_dot) {
  if (name.empty() || name == "." || name == "..") return false;
  return std::all_of(name.begin(), name.end(), [allow_dot](char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || (allow_dot && c == '.');
  });
}

}  // namespace contactbench
