// A scene written back: an ordered tree of keys (a TOML or JSON table keeps no order, and the methods'
// order matters), which app/scene_writer.cpp renders as TOML or, through the JSON writer, as JSON. The
// schema and each method put their own keys (defaults filled in) in it.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "contactbench/core/types.hpp"

namespace contactbench {

struct SceneKeys {
  using Value =
      std::variant<Real, std::int64_t, bool, std::string, std::vector<Real>, std::vector<std::string>>;

  std::string name;  // of this table in its parent ("" at the top)
  std::vector<std::pair<std::string, Value>> values;
  std::vector<SceneKeys> tables;  // sub-tables, in order

  // Out of line: GCC 12 inlining a variant of vectors into callers warns of a maybe-uninitialized member.
  void put(std::string key, Value value);
  void put(std::string key, const char* value) { put(std::move(key), Value{std::string(value)}); }
  SceneKeys& table(std::string table_name) {
    tables.push_back(SceneKeys{.name = std::move(table_name), .values = {}, .tables = {}});
    return tables.back();
  }
};

}  // namespace contactbench
