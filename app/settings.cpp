#include "contactbench/app/settings.hpp"

#include <charconv>

#include "contactbench/app/json_writer.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_text.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

std::function<bool(const SettingValue&)> in_range(double low, double high) {
  return [low, high](const SettingValue& v) {
    const double x = std::holds_alternative<std::int64_t>(v) ? static_cast<double>(std::get<std::int64_t>(v))
                                                             : std::get<double>(v);
    return x >= low && x <= high;
  };
}

std::string kind_text(SettingKind kind) {
  switch (kind) {
    case SettingKind::boolean:
      return "true or false";
    case SettingKind::integer:
      return "an integer";
    case SettingKind::number:
      return "a number";
    case SettingKind::choice:
    case SettingKind::text:
      return "a string";
  }
  return "";
}

std::string value_text(const SettingValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>)
          return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, std::int64_t>)
          return std::to_string(v);
        else if constexpr (std::is_same_v<T, double>)
          return exact_number(v);
        else
          return "\"" + v + "\"";
      },
      value);
}

std::optional<SettingValue> read_setting(const Section& section, const SettingSpec& spec) {
  const auto passes = [&](const SettingValue& v) { return !spec.ok || spec.ok(v); };
  switch (spec.kind) {
    case SettingKind::boolean:
      if (const auto v = section.boolean(spec.key)) return SettingValue(*v);
      break;
    case SettingKind::integer:
      if (const auto v = section.integer(
              spec.key, false, {[&](std::int64_t x) { return passes(SettingValue(x)); }, spec.accepted}))
        return SettingValue(*v);
      break;
    case SettingKind::number:
      if (const auto v = section.number(spec.key, false,
                                        {[&](Real x) { return passes(SettingValue(x)); }, spec.accepted}))
        return SettingValue(*v);
      break;
    case SettingKind::choice: {
      const std::vector<std::string_view> choices(spec.choices.begin(), spec.choices.end());
      if (const auto v = section.choice(spec.key, choices)) return SettingValue(*v);
      break;
    }
    case SettingKind::text:
      if (const auto v = section.string(spec.key, false, spec.accepted)) return SettingValue(*v);
      break;
  }
  return std::nullopt;
}

void put_setting(SceneKeys& keys, const std::string& key, const SettingValue& value) {
  std::visit([&](const auto& v) { keys.put(key, v); }, value);
}

SettingValue checked_setting(const SettingSpec& spec, SettingValue value, const std::string& where) {
  if (spec.kind == SettingKind::number && std::holds_alternative<std::int64_t>(value))
    value = static_cast<double>(std::get<std::int64_t>(value));
  const bool right_kind = std::visit(
      [&](const auto& v) {
        using T = std::decay_t<decltype(v)>;
        switch (spec.kind) {
          case SettingKind::boolean:
            return std::is_same_v<T, bool>;
          case SettingKind::integer:
            return std::is_same_v<T, std::int64_t>;
          case SettingKind::number:
            return std::is_same_v<T, double>;
          default:
            return std::is_same_v<T, std::string>;
        }
      },
      value);
  std::string accepted = spec.accepted;
  if (spec.kind == SettingKind::choice) {
    accepted.clear();
    for (const std::string& c : spec.choices)
      accepted += (accepted.empty() ? "\"" : ", \"") + c + "\"";
  }
  const auto refuse = [&](const std::string& reason) -> SettingValue {
    throw Error(where + ": " + reason +
                "; accepted: " + (accepted.empty() ? kind_text(spec.kind) : accepted));
  };
  if (!right_kind)
    return refuse("wrong type: expected " + kind_text(spec.kind) + ", got " + value_text(value));
  if (spec.kind == SettingKind::choice &&
      std::find(spec.choices.begin(), spec.choices.end(), std::get<std::string>(value)) == spec.choices.end())
    return refuse("unknown choice " + value_text(value));
  if (spec.ok && !spec.ok(value)) return refuse("out of range: got " + value_text(value));
  return value;
}

}  // namespace contactbench
