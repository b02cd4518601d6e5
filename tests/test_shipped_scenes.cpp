// Every scene the project ships (scenes/**/*.toml) is read and passes every method's preflight, as
// `contactbench run SCENE` would do it, and the run is stopped at the first stage of real work (a sweep, a
// BEM solve, a theory): a shipped study that a change of the schema or of a method's checks makes unrunnable
// is found by every ctest, not after hours of a study run (before, the scenes were only parsed, as fuzz
// seeds).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/scene_run.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

// Thrown by the observer at the first stage after the inputs (the surface and its moments): the preflight
// passed.
struct PreflightPassed {
  std::string stage;
};

std::vector<fs::path> shipped_scenes() {
  std::vector<fs::path> scenes;
  for (const fs::directory_entry& entry :
       fs::recursive_directory_iterator(fs::path(CB_SOURCE_DIR) / "scenes"))
    if (entry.is_regular_file() && entry.path().extension() == ".toml") scenes.push_back(entry.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(EveryShippedScene, IsReadAndPassesEveryPreflight) {
  const std::vector<fs::path> scenes = shipped_scenes();
  // scenes/paper and scenes/studies: 17 files when this test was written; fewer means the glob broke.
  ASSERT_GE(scenes.size(), 17u);
  RunObserver observer;
  observer.stage_started = [](const std::string& stage) {
    if (stage != "surface" && stage != "moments") throw PreflightPassed{stage};
  };
  for (const fs::path& path : scenes) {
    SCOPED_TRACE(path.string());
    try {
      const Scene scene = read_scene(path);
      EXPECT_FALSE(scene.methods.empty());
      run_scene(scene, {.threads = 1, .observer = &observer});
      ADD_FAILURE() << path << ": ran to the end without a stage of work";
    } catch (const PreflightPassed&) {
      // the inputs were made, every preflight passed, and the first stage of work was about to start
    } catch (const SceneError& e) {
      std::string problems;
      for (const std::string& problem : e.problems())
        problems += "\n  " + problem;
      ADD_FAILURE() << path << " is refused:" << problems;
    } catch (const std::exception& e) {
      ADD_FAILURE() << path << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace contactbench
