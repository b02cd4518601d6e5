#include "contactbench/app/scene_toml.hpp"

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

void Problems::add(long line, std::string_view path, std::string_view reason, std::string_view accepted) {
  std::string text = origin_;
  if (line > 0) text.append(":").append(std::to_string(line));
  text.append(": ").append(path).append(": ").append(reason);
  if (!accepted.empty()) text.append("; accepted: ").append(accepted);
  lines_.push_back(std::move(text));
}

void Problems::add_syntax_error(long line, long column, std::string_view reason) {
  lines_.push_back(origin_ + ":" + std::to_string(line) + ":" + std::to_string(column) +
                   ": TOML syntax error: " + std::string(reason));
}

void Problems::throw_if_any() const {
  if (lines_.empty()) return;
  std::string message = "invalid scene " + origin_ + " (" + std::to_string(lines_.size()) +
                        (lines_.size() == 1 ? " problem):" : " problems):");
  for (const auto& line : lines_)
    message.append("\n").append(line);
  throw SceneError(message, lines_);
}

Rule<Real> positive(std::string_view unit) {
  return {[](Real v) { return std::isfinite(v) && v > 0; }, "a finite number > 0 " + std::string(unit)};
}
Rule<Real> open_interval(Real low, Real high, std::string_view text) {
  return {[low, high](Real v) { return v > low && v < high; }, std::string(text)};
}
Rule<std::int64_t> int_range(std::int64_t low, std::int64_t high) {
  return {[low, high](std::int64_t v) { return v >= low && v <= high; },
          "an integer in [" + std::to_string(low) + ", " + std::to_string(high) + "]"};
}

long line_of(const toml::node& node) {
  return static_cast<long>(node.source().begin.line);
}

std::string_view type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

std::string Section::key_path(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

void Section::problem(std::string_view key, std::string_view reason, std::string_view accepted) const {
  const toml::node* node = find(key);
  problems_.add(node ? line_of(*node) : line(), key_path(key), reason, accepted);
}

void Section::missing(std::string_view key, std::string_view accepted) const {
  problem(key, "missing required key", accepted);
}

void Section::wrong_type(std::string_view key, std::string_view expected, std::string_view accepted) const {
  problem(key,
          "wrong type: expected " + std::string(expected) + ", got " + std::string(type_name(*find(key))),
          accepted);
}

void Section::reject_unknown(const std::vector<std::string_view>& accepted) const {
  std::vector<std::string> names(accepted.begin(), accepted.end());
  names.insert(names.end(), common_keys_.begin(), common_keys_.end());
  for (auto&& [key, node] : table_)
    if (std::find(names.begin(), names.end(), key.str()) == names.end())
      problems_.add(line_of(node), key_path(key.str()), "unknown key", join(names));
}

std::optional<Real> Section::number(std::string_view key, bool required, const Rule<Real>& rule) const {
  const toml::node* node = find(key);
  if (!node) {
    if (required) missing(key, rule.accepted);
    return std::nullopt;
  }
  const auto value = as_real(*node);
  if (!value) {
    wrong_type(key, "a number", rule.accepted);
    return std::nullopt;
  }
  if (!rule.ok(*value)) {
    problem(key, "out of range: got " + exact_number(*value), rule.accepted);
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> Section::integer(std::string_view key, bool required,
                                             const Rule<std::int64_t>& rule) const {
  const toml::node* node = find(key);
  if (!node) {
    if (required) missing(key, rule.accepted);
    return std::nullopt;
  }
  const auto* value = node->as_integer();
  if (!value) {
    wrong_type(key, "an integer", rule.accepted);
    return std::nullopt;
  }
  if (!rule.ok(value->get())) {
    problem(key, "out of range: got " + std::to_string(value->get()), rule.accepted);
    return std::nullopt;
  }
  return value->get();
}

std::optional<std::string> Section::string(std::string_view key, bool required,
                                           std::string_view accepted) const {
  const toml::node* node = find(key);
  if (!node) {
    if (required) missing(key, accepted);
    return std::nullopt;
  }
  const auto* value = node->as_string();
  if (!value) {
    wrong_type(key, "a string", accepted);
    return std::nullopt;
  }
  return value->get();
}

std::optional<std::string> Section::choice(std::string_view key,
                                           const std::vector<std::string_view>& choices) const {
  std::vector<std::string> quoted;
  for (const auto choice : choices)
    quoted.push_back("\"" + std::string(choice) + "\"");
  const auto value = string(key, false, join(quoted));
  if (value && std::find(choices.begin(), choices.end(), *value) == choices.end()) {
    problem(key, "unknown choice \"" + *value + "\"", join(quoted));
    return std::nullopt;
  }
  return value;
}

std::optional<bool> Section::boolean(std::string_view key) const {
  const toml::node* node = find(key);
  if (!node) return std::nullopt;
  const auto* value = node->as_boolean();
  if (!value) {
    wrong_type(key, "a boolean", "true, false");
    return std::nullopt;
  }
  return value->get();
}

const toml::table* Section::subtable(std::string_view key, bool required, std::string_view accepted) const {
  const toml::node* node = find(key);
  if (!node) {
    if (required) missing(key, accepted);
    return nullptr;
  }
  const auto* value = node->as_table();
  if (!value) wrong_type(key, "a table", accepted);
  return value;
}

std::optional<Real> Section::as_real(const toml::node& node) {
  if (const auto* value = node.as_floating_point()) return value->get();
  if (const auto* value = node.as_integer()) return static_cast<Real>(value->get());
  return std::nullopt;
}

}  // namespace contactbench
