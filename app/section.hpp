// One table of a scene's TOML and its key path: typed values read with their accepted ranges, every problem
// reported at the key a user would change (app/problems.hpp). The schema (app/scene_schema.cpp), the
// interface (app/interface.cpp), the settings declarations (app/settings.hpp) and each method's own keys read
// through it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "contactbench/app/problems.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// An accepted range: the test and its description for messages.
template <typename T>
struct Rule {
  std::function<bool(T)> ok;
  std::string accepted;
};

Rule<Real> positive(std::string_view unit);
Rule<Real> open_interval(Real low, Real high, std::string_view text);
Rule<std::int64_t> int_range(std::int64_t low, std::int64_t high);

long line_of(const toml::node& node);
std::string_view type_name(const toml::node& node);

// One table of the file and its key path; reads typed values and reports what is wrong with them.
class Section {
 public:
  Section(const toml::table& table, std::string path, Problems& problems, bool root = false)
      : table_(table), path_(std::move(path)), problems_(problems), root_(root) {}

  const toml::table& table() const { return table_; }
  const std::string& path() const { return path_; }
  Problems& problems() const { return problems_; }
  std::string key_path(std::string_view key) const;
  bool has(std::string_view key) const { return table_.contains(key); }
  const toml::node* find(std::string_view key) const { return table_.get(key); }
  // The table's own line (0 for the whole file, whose "line" would point at its first key).
  long line() const { return root_ ? 0 : line_of(table_); }

  // A problem with `key`: at the key's line when present, else at the table's.
  void problem(std::string_view key, std::string_view reason, std::string_view accepted = {}) const;
  void missing(std::string_view key, std::string_view accepted) const;
  void wrong_type(std::string_view key, std::string_view expected, std::string_view accepted) const;
  // Reports every key not in `accepted` nor in the common keys, listing those accepted here.
  void reject_unknown(const std::vector<std::string_view>& accepted) const;
  // Keys every table of its kind has, read by the schema rather than by the table's owner (a method's
  // `ignore`): reject_unknown accepts them too.
  void accept_common_keys(std::vector<std::string> keys) { common_keys_ = std::move(keys); }

  // A number (integers are accepted where a float is expected).
  std::optional<Real> number(std::string_view key, bool required, const Rule<Real>& rule) const;
  std::optional<std::int64_t> integer(std::string_view key, bool required,
                                      const Rule<std::int64_t>& rule) const;
  std::optional<std::string> string(std::string_view key, bool required, std::string_view accepted) const;
  // One of `choices` (a string); a problem listing them otherwise.
  std::optional<std::string> choice(std::string_view key, const std::vector<std::string_view>& choices) const;
  std::optional<bool> boolean(std::string_view key) const;
  // A sub-table ([path.key] or key = { ... }).
  const toml::table* subtable(std::string_view key, bool required, std::string_view accepted) const;

  static std::optional<Real> as_real(const toml::node& node);

 private:
  const toml::table& table_;
  std::string path_;
  Problems& problems_;
  bool root_;
  std::vector<std::string> common_keys_;
};

}  // namespace contactbench
