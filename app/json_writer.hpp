// A small writer for JSON objects with exact numbers (shortest decimal form that reads back to the same
// double).
#pragma once

#include <memory>
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

  // The object, one member per line, nested objects indented two spaces per level.
  std::string str() const { return render(0); }

 private:
  struct Member {
    std::string key;
    std::string scalar;                  // rendered value, or empty when `object` is set
    std::shared_ptr<JsonObject> object;  // a nested object
  };
  std::string render(int level) const;
  std::vector<Member> members_;
};

std::string json_quote(std::string_view text);
std::string json_number(double value);

}  // namespace contactbench
