// The problems of a scene, collected with the file, the line and the key path ("methods.bem.tolerance") and
// the values accepted there; one SceneError lists them all at the end (scenes/README.md, Errors).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "contactbench/app/scene_error.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

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

}  // namespace contactbench
