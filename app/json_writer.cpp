#include "contactbench/app/json_writer.hpp"

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

void JsonObject::add_scalar(std::string_view key, std::string text) {
  Member member;
  member.key = key;
  member.scalar = std::move(text);
  members_.push_back(std::move(member));
}

JsonObject& JsonObject::add(std::string_view key, double value) {
  add_scalar(key, json_number(value));
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, long long value) {
  add_scalar(key, std::to_string(value));
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, bool value) {
  add_scalar(key, value ? "true" : "false");
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, std::string_view value) {
  add_scalar(key, json_quote(value));
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, JsonObject nested) {
  Member member;
  member.key = key;
  member.object = std::make_shared<JsonObject>(std::move(nested));
  members_.push_back(std::move(member));
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, std::span<const double> values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i == 0 ? "" : ", ") + json_number(values[i]);
  add_scalar(key, text + "]");
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, std::span<const std::string> values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i == 0 ? "" : ", ") + json_quote(values[i]);
  add_scalar(key, text + "]");
  return *this;
}

JsonObject& JsonObject::add(std::string_view key, std::vector<JsonObject> objects) {
  Member member;
  member.key = key;
  member.objects = std::move(objects);
  member.is_array = true;
  members_.push_back(std::move(member));
  return *this;
}

JsonObject& JsonObject::add_strings(std::string_view key, const std::vector<std::string>& values) {
  std::string text = "[";
  for (std::size_t i = 0; i < values.size(); ++i)
    text += (i == 0 ? "" : ", ") + json_quote(values[i]);
  add_scalar(key, text + "]");
  return *this;
}

JsonObject& JsonObject::add_raw(std::string_view key, std::string json) {
  add_scalar(key, std::move(json));
  return *this;
}

std::string JsonObject::render(int level) const {
  const std::string pad(2 * (level + 1), ' ');
  std::string out = "{";
  for (std::size_t i = 0; i < members_.size(); ++i) {
    const Member& m = members_[i];
    out += (i == 0 ? "\n" : ",\n") + pad + json_quote(m.key) + ": ";
    if (m.is_array) {
      const std::string item_pad(2 * (level + 2), ' ');
      out += "[";
      for (std::size_t k = 0; k < m.objects.size(); ++k)
        out += (k == 0 ? "\n" : ",\n") + item_pad + m.objects[k].render(level + 2);
      out += m.objects.empty() ? "]" : "\n" + pad + "]";
    } else {
      out += m.object ? m.object->render(level + 1) : m.scalar;
    }
  }
  out += members_.empty() ? "}" : "\n" + std::string(2 * level, ' ') + "}";
  return out;
}

}  // namespace contactbench
