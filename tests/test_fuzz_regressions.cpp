// Replays fuzz/regressions/ (fuzz/regressions/README.md): every input that once broke a parser, and hand-made
// hostile ones, must now load or be refused with contactbench::Error; never another exception, a crash or a
// hang.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/app/scene.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;
const fs::path kRegressions = fs::path(CB_SOURCE_DIR) / "fuzz" / "regressions";

std::vector<fs::path> inputs(const std::string& target) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(kRegressions / target))
    if (entry.is_regular_file()) files.push_back(entry.path());
  return files;
}

// Ok when the call returns or throws Error; any other exception fails the test with the input's name.
template <class Call>
void expect_load_or_clear_refusal(const fs::path& input, Call call) {
  try {
    call();
  } catch (const Error&) {
    // a refusal with a message
  } catch (const std::exception& e) {
    ADD_FAILURE() << input << ": unexpected " << typeid(e).name() << ": " << e.what();
  }
}

TEST(FuzzRegressions, TopographyInputsLoadOrAreRefused) {
  const std::vector<fs::path> files = inputs("topography");
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    expect_load_or_clear_refusal(file, [&] {
      const Surface surface = read_topography(file);
      // What loads is usable: finite heights, so no NaN reaches a method.
      EXPECT_TRUE(surface.heights().allFinite()) << file;
    });
  }
}

TEST(FuzzRegressions, SceneInputsParseOrAreRefused) {
  const std::vector<fs::path> files = inputs("scene");
  ASSERT_FALSE(files.empty());
  for (const fs::path& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    expect_load_or_clear_refusal(
        file, [&] { (void)parse_scene(text.str(), "/nonexistent/contactbench/scene.toml"); });
  }
}

}  // namespace
}  // namespace contactbench
