// A scene given as TOML text, parsed and run on one thread without progress output: the pipeline tests'
// shortest way from a scene to its report.
#pragma once

#include <filesystem>
#include <string>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_run.hpp"

namespace contactbench {

// `origin` stands for the scene file's path (relative paths in the text are read from its folder).
inline SceneReport run_scene_text(const std::string& text,
                                  const std::filesystem::path& origin = "test.toml") {
  return run_scene(parse_scene(text, origin), {.threads = 1, .observer = nullptr});
}

}  // namespace contactbench
