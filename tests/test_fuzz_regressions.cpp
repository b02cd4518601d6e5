// Replays fuzz/regressions/ (fuzz/regressions/README.md): every input that once broke a parser, and hand-made
// hostile ones, read exactly as the fuzz targets read them (fuzz/fuzz_topography.cpp: the format detected
// from the content and a lateral size of 1e-5 m given to the formats that carry none; fuzz/fuzz_scene.cpp:
// parsed against a folder that does not exist). Each file has a stated outcome in the EXPECTED manifest
// beside it: refused with contactbench::Error whose message contains a given text, or loaded with a given
// size (parsed, for scenes). Another exception, a different outcome, a file without a line, or a line without
// a file fails the test and says what to write.
//
// Before, a file was read without the fuzzer's lateral size, so a plain matrix or .npy input was refused
// early ("needs a lateral size") and its crash in the levelling never replayed; and any outcome passed: a
// regression that turned a refusal into a load of garbage (or the reverse) went unseen.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
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
constexpr const char* kManifest = "EXPECTED";

// The inputs of a target: every regular file but the manifest.
std::vector<fs::path> inputs(const std::string& target) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(kRegressions / target))
    if (entry.is_regular_file() && entry.path().filename() != kManifest) files.push_back(entry.path());
  return files;
}

// The manifest: one line a file, `<file name> <outcome>`, the outcome `refused <text in the message>`,
// `loads <nx> x <ny>` (topography) or `parses` (scene); blank lines and lines from # on are ignored.
std::map<std::string, std::string> manifest(const std::string& target) {
  std::map<std::string, std::string> expected;
  std::ifstream in(kRegressions / target / kManifest);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::size_t space = line.find(' ');
    if (space == std::string::npos) {
      ADD_FAILURE() << target << "/" << kManifest << ": a line without an outcome: " << line;
      continue;
    }
    expected[line.substr(0, space)] = line.substr(space + 1);
  }
  return expected;
}

// What happened to one input, in the manifest's words. A refusal keeps the whole message; any exception other
// than contactbench::Error is a failure of the parser, reported as such.
struct Outcome {
  bool refused = false;
  std::string text;  // the message of a refusal, or "loads <nx> x <ny>" / "parses"
};

template <class Call>
Outcome outcome_of(const fs::path& input, Call call) {
  try {
    return {.refused = false, .text = call()};
  } catch (const Error& e) {
    return {.refused = true, .text = e.what()};
  } catch (const std::exception& e) {
    ADD_FAILURE() << input << ": unexpected " << typeid(e).name() << ": " << e.what();
    return {.refused = true, .text = "(not a contactbench::Error)"};
  }
}

// Compares each file's outcome with its line; a missing line fails with the line to add.
template <class Read>
void replay(const std::string& target, Read read) {
  const std::vector<fs::path> files = inputs(target);
  ASSERT_FALSE(files.empty());
  std::map<std::string, std::string> expected = manifest(target);
  for (const fs::path& file : files) {
    const std::string name = file.filename().string();
    const Outcome got = outcome_of(file, [&] { return read(file); });
    const auto line = expected.find(name);
    if (line == expected.end()) {
      ADD_FAILURE() << "fuzz/regressions/" << target << "/" << name << " has no line in fuzz/regressions/"
                    << target << "/" << kManifest << ". It is " << (got.refused ? "refused: " : "")
                    << got.text << "\nIf that is right, add the line\n  " << name << " "
                    << (got.refused ? "refused <a distinctive part of the message above>" : got.text);
      continue;
    }
    const std::string& want = line->second;
    if (want.rfind("refused ", 0) == 0) {
      const std::string cause = want.substr(8);
      EXPECT_TRUE(got.refused) << name << ": expected a refusal (" << cause << "), but it " << got.text;
      if (got.refused) {
        EXPECT_NE(got.text.find(cause), std::string::npos) << name << ": refused, but with: " << got.text;
      }
    } else {
      EXPECT_FALSE(got.refused) << name << ": expected `" << want << "`, but refused: " << got.text;
      if (!got.refused) {
        EXPECT_EQ(got.text, want) << name;
      }
    }
    expected.erase(line);
  }
  for (const auto& [name, want] : expected)
    ADD_FAILURE() << target << "/" << kManifest << " names " << name << " (" << want
                  << "), which is not in fuzz/regressions/" << target << "/: remove the line";
}

TEST(FuzzRegressions, TopographyInputsHaveTheirStatedOutcome) {
  replay("topography", [](const fs::path& file) {
    // As fuzz/fuzz_topography.cpp reads it.
    TopographyReadOptions options;
    if (!format_carries_sizes(detect_topography_format(file))) options.lx = 1e-5;
    const Surface surface = read_topography(file, options);
    (void)surface.rms_height();
    // What loads is usable: finite heights, so no NaN reaches a method.
    EXPECT_TRUE(surface.heights().allFinite()) << file;
    return "loads " + std::to_string(surface.grid().nx) + " x " + std::to_string(surface.grid().ny);
  });
}

TEST(FuzzRegressions, SceneInputsHaveTheirStatedOutcome) {
  replay("scene", [](const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    // As fuzz/fuzz_scene.cpp parses it.
    (void)parse_scene(text.str(), "/nonexistent/contactbench-fuzz/scene.toml");
    return std::string("parses");
  });
}

}  // namespace
}  // namespace contactbench
