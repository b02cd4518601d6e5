// A small writer for JSON objects with exact numbers (shortest decimal form that reads back to the same
// double).
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace contactbench {

class JsonObject {
 public:
  JsonObject& add(std::string_view key, double value);  // non-finite values are written as null
  JsonObject& add(std::string_view key, long long value);
  JsonObject& add(std::string_view key, int value) { return add(key, static_cast<long long>(value)); }
  JsonObject& add(std::string_view key, long value) { return add(key, static_cast<long long>(value)); }
  JsonObject& add(std::string_view key, bool value);
  JsonObject& add(std::string_view key, std::string_view value);
  JsonObject& add(std::string_view key, const char* value) { return add(key, std::string_view(value)); }
  JsonObject& add(std::string_view key, JsonObject nested);
  JsonObject& add(std::string_view key, std::span<const double> values);  // an array of numbers, one line
  JsonObject& add(std::string_view key, std::span<const std::string> values);  // an array of strings
  JsonObject& add(std::string_view key, std::vector<JsonObject> objects);      // an array of objects
  JsonObject& add_strings(std::string_view key, const std::vector<std::string>& values);
  // A value that is already JSON (e.g. a document another writer made), inserted as it is.
  JsonObject& add_raw(std::string_view key, std::string json);

  // The object, one member per line, nested objects indented two spaces per level.
  std::string str() const { return render(0); }

 private:
  struct Member {
    std::string key;
    std::string scalar;                  // rendered value, or empty when `object` or `objects` is set
    std::shared_ptr<JsonObject> object;  // a nested object
    std::vector<JsonObject> objects;     // an array of objects (when is_array)
    bool is_array = false;
  };
  void add_scalar(std::string_view key, std::string text);
  std::string render(int level) const;
  std::vector<Member> members_;
};

std::string json_quote(std::string_view text);
std::string json_number(double value);

}  // namespace contactbench
