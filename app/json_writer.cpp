#include "app/json_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace contactbench {

std::string json_quote(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(ch));
          out += escaped;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

JsonObject& JsonObject::add(std::string_view key, double value) {
  members_.push_back({std::string(key), json_number(value), nullptr});
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, long long value) {
  members_.push_back({std::string(key), std::to_string(value), nullptr});
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, bool value) {
  members_.push_back({std::string(key), value ? "true" : "false", nullptr});
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, std::string_view value) {
  members_.push_back({std::string(key), json_quote(value), nullptr});
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, JsonObject nested) {
  members_.push_back({std::string(key), "", std::make_shared<JsonObject>(std::move(nested))});
  return *this;
}

std::string JsonObject::render(int level) const {
  const std::string pad(2 * (level + 1), ' ');
  std::string out = "{";
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const Member& m = members_[i];
    out += (i == 0 ? "\n" : ",\n") + pad + json_quote(m.key) + ": ";
    out += m.object ? m.object->render(level + 1) : m.scalar;
  }
  out += members_.empty() ? "}" : "\n" + std::string(2 * level, ' ') + "}";
  return out;
}

}  // namespace contactbench
