// Reading a scene's TOML with key paths: every problem is collected with the file, the line and the key path
// ("methods.bem.tolerance") and the values accepted there, and one SceneError lists them all at the end
// (scenes/README.md, Errors). The schema (app/scene_schema.cpp) and each method's own keys
// (app/methods/) read their tables through Section.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// Points a side of any grid a scene may ask for: 65536^2 doubles are already 32 GiB.
inline constexpr Index kMaxPointsASide = 65536;

// Shortest decimal that reads back to the same double (messages must not round a value into the range).
std::string exact_number(Real value);
std::string join(const std::vector<std::string>& items);

// Names become folder names (results/<name>/) and labels become column and file names: keep them portable.
bool portable_name(std::string_view name, bool allow_dot);

// Every problem found, each formatted as "<origin>[:line]: <key path>: <reason>[; accepted: ...]".
class Problems {
 public:
  explicit Problems(std::string origin) : origin_(std::move(origin)) {}

  void add(long line, std::string_view path, std::string_view reason, std::string_view accepted = {});
  // A problem whose location is not a key (a TOML syntax error, at "<origin>:line:column").
  void add_syntax_error(long line, long column, std::string_view reason);
  std::size_t count() const { return lines_.size(); }
  // Throws one SceneError listing every problem, if there is any.
  void throw_if_any() const;

 private:
  std::string origin_;
  std::vector<std::string> lines_;
};

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

// Validates a group of keys and, when all of them are valid, runs the stricter check of a library function
// that throws Error: its message becomes one problem at `path`.
template <typename Check>
void library_check(Problems& problems, std::size_t count_before, long line, std::string_view path,
                   Check check) {
  if (problems.count() != count_before) return;  // its message would repeat one already given
  try {
    check();
  } catch (const Error& error) {
    problems.add(line, path, error.what());
  }
}

// parse_scene (app/scene.hpp) of a document already parsed, or built by a command from its flags.
Scene parse_scene_table(const toml::table& document, const std::filesystem::path& origin);

}  // namespace contactbench
