// The error of a scene that cannot run: every problem it has, one per line of the message
// ("<origin>[:line]: <key path>: <reason>; accepted: ..."), found when the file is read or when the methods
// check themselves against the surface, material and loads before any stage (app/scene_run.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"

namespace contactbench {

class SceneError : public Error {
 public:
  SceneError(const std::string& message, std::vector<std::string> problems)
      : Error(message), problems_(std::move(problems)) {}
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

}  // namespace contactbench
