// A scene's `approach_retract = { from, to, steps }` (issue 34: the loading and unloading path in scenes):
// each adhesive BEM runs the closed separation-controlled path after its loads, the same path the library
// gives (bem/adhesive_path.hpp), written as <label>_approach_retract.csv and summarised in summary.json;
// a scene that cannot run it is refused naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "contactbench/app/adhesive_path_csv.hpp"
#include "contactbench/app/comparison.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/app/surface_source.hpp"
#include "contactbench/bem/adhesive_path.hpp"

namespace contactbench {
namespace {

// The paper's surface A on 32 x 32 points (sigma = 0.5 um, its tallest peak about 1.5 um above the mean
// plane) made of a soft solid with Maugis-Dugdale adhesion (w = 50 mJ/m^2, sigma0 = 0.1 MPa: the range
// w/sigma0 = 0.5 um). The path starts 2.5 um above the mean plane, out of reach, and turns at a mean gap of
// 0.5 um (on the periodic problem the separation is the mean gap: about a quarter of the surface in contact).
const std::string kSoftAdhesive = R"(
[surface]
generate = { sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, size = 200e-6, grid = 32, seed = 2 }
[material]
E = 3e6
nu = 0.49
[loads]
values = [1e-3, 1e-2]
)";

std::string scene_with(const std::string& top, const std::string& interface, const std::string& methods) {
  return "name = \"path\"\n" + top + kSoftAdhesive + interface + methods;
}

const std::string kAdhesion = "[interface]\nadhesion = { model = \"dugdale\", work = 0.05, stress = 1e5 }\n";
const std::string kApproachRetract = "approach_retract = { from = 2.5e-6, to = 0.5e-6, steps = 12 }\n";

std::string refusal(const std::string& text) {
  try {
    parse_scene(text, "test.toml");
  } catch (const SceneError& error) {
    return error.what();
  }
  return "";
}

TEST(ApproachRetractScene, TheRunsPathIsTheLibrarysPath) {
  const Scene scene = parse_scene(
      scene_with(kApproachRetract, kAdhesion,
                 "[methods.bem]\n[methods.bem_plain]\nmethod = \"bem\"\nignore = [\"adhesion\"]\n"),
      "test.toml");
  ASSERT_TRUE(scene.approach_retract.has_value());
  // The key survives the scene's round trip through its TOML.
  const Scene again = parse_scene(to_toml(scene), "again.toml");
  ASSERT_TRUE(again.approach_retract.has_value());
  EXPECT_EQ(again.approach_retract->start, 2.5e-6);
  EXPECT_EQ(again.approach_retract->turn, 0.5e-6);
  EXPECT_EQ(again.approach_retract->steps, 12);

  const SceneReport report = run_scene(scene, {.threads = 1, .observer = nullptr});
  const MethodCurve& adhesive = report.methods[0].curve;
  ASSERT_TRUE(adhesive.approach_retract.has_value());
  EXPECT_FALSE(report.methods[1].curve.approach_retract.has_value());  // the BEM that ignores the adhesion
  const AdhesivePath& path = *adhesive.approach_retract;
  ASSERT_TRUE(path.converged);
  ASSERT_EQ(path.states.size(), 25u);  // 12 steps down, 12 up, and the start

  // The same path from a fresh adhesive solver with the scene's settings (active_set, tolerance 1e-8).
  // The stage solved its loads before the path and the path forgets them; equal to the solver's tolerance:
  // each state's load within 1e-6 of the path's load range (the pressure's relative change at convergence is
  // 1e-8, a state's load a mean of it over the grid), and the same contact nodes.
  const Surface surface = make_surface(scene.surface, 1);
  AdhesiveBemSolver solver(surface, scene.material.estar, *scene.interface.adhesion,
                           AdhesiveSolverOptions{.contact = {.tolerance = 1e-8}}, 1);
  const AdhesivePath direct = approach_retract(solver, {.start = 2.5e-6, .turn = 0.5e-6, .steps = 12});
  ASSERT_EQ(direct.states.size(), path.states.size());
  Real low = 0, high = 0;
  for (const AdhesivePathState& s : direct.states) {
    low = std::min(low, s.mean_pressure);
    high = std::max(high, s.mean_pressure);
  }
  ASSERT_GT(high - low, 0);
  for (std::size_t k = 0; k < path.states.size(); ++k) {
    EXPECT_EQ(path.states[k].separation, direct.states[k].separation) << k;
    EXPECT_NEAR(path.states[k].mean_pressure, direct.states[k].mean_pressure, 1e-6 * (high - low)) << k;
    EXPECT_EQ(path.states[k].contact_points, direct.states[k].contact_points) << k;
  }
  EXPECT_EQ(path.jumps.size(), direct.jumps.size());
  EXPECT_NEAR(path.pull_off_pressure, direct.pull_off_pressure, 1e-6 * (high - low));
  // The path is adhesive: it pulls (a tensile state) on the way out.
  EXPECT_LT(path.pull_off_pressure, 0);

  // Written beside the curves, stamped, one row per state; summarised in summary.json.
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "contactbench_path_scene";
  std::filesystem::remove_all(folder);
  write_report(folder, report, compare(report), current_provenance(1, "contactbench run test.toml"));
  std::ifstream in(folder / "bem_approach_retract.csv");
  ASSERT_TRUE(in);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# contactbench run of scene path, bem: approach-retract path (commit ", 0), 0u)
      << line;
  std::size_t rows = 0;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      EXPECT_EQ(line, kAdhesivePathColumns);
      header = true;
    } else {
      ++rows;
    }
  }
  EXPECT_EQ(rows, 25u);
  EXPECT_FALSE(std::filesystem::exists(folder / "bem_plain_approach_retract.csv"));
  std::ifstream summary(folder / "summary.json");
  const std::string json((std::istreambuf_iterator<char>(summary)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"approach_retract\""), std::string::npos);
  EXPECT_NE(json.find("\"pull_off_load\""), std::string::npos);
  std::filesystem::remove_all(folder);
}

TEST(ApproachRetractScene, NothingRunsWithoutTheKey) {
  const SceneReport report = run_scene(parse_scene(scene_with("", kAdhesion, "[methods.bem]\n"), "test.toml"),
                                       {.threads = 1, .observer = nullptr});
  EXPECT_FALSE(report.methods[0].curve.approach_retract.has_value());
}

TEST(ApproachRetractScene, RefusedNamingTheKey) {
  // No adhesion: nothing to jump.
  std::string why = refusal(scene_with(kApproachRetract, "", "[methods.bem]\n"));
  EXPECT_NE(why.find("approach_retract"), std::string::npos) << why;
  EXPECT_NE(why.find("no interface.adhesion"), std::string::npos) << why;
  // Every BEM ignores the adhesion.
  why = refusal(scene_with(kApproachRetract, kAdhesion, "[methods.bem]\nignore = [\"adhesion\"]\n"));
  EXPECT_NE(why.find("every bem method of this scene ignores"), std::string::npos) << why;
  // The turn must lie below the start.
  why = refusal(scene_with("approach_retract = { from = 1e-6, to = 2e-6, steps = 12 }\n", kAdhesion,
                           "[methods.bem]\n"));
  EXPECT_NE(why.find("approach_retract.to"), std::string::npos) << why;
  // Too few steps, an unknown key, a missing one.
  why = refusal(
      scene_with("approach_retract = { from = 1e-6, to = 0.0, steps = 1 }\n", kAdhesion, "[methods.bem]\n"));
  EXPECT_NE(why.find("approach_retract.steps"), std::string::npos) << why;
  why = refusal(scene_with("approach_retract = { from = 1e-6, to = 0.0, steps = 4, step = 2 }\n", kAdhesion,
                           "[methods.bem]\n"));
  EXPECT_NE(why.find("approach_retract.step"), std::string::npos) << why;
  why = refusal(scene_with("approach_retract = { from = 1e-6, steps = 4 }\n", kAdhesion, "[methods.bem]\n"));
  EXPECT_NE(why.find("approach_retract.to"), std::string::npos) << why;
  // On the periodic problem the separation is the mean gap: a turn at 0 m needs an infinite load, refused
  // in preflight before any stage.
  try {
    run_scene(parse_scene(scene_with("approach_retract = { from = 1e-6, to = 0.0, steps = 4 }\n", kAdhesion,
                                     "[methods.bem]\n"),
                          "test.toml"),
              {.threads = 1, .observer = nullptr});
    FAIL() << "a periodic path turning at 0 m was run";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("approach_retract.to"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace contactbench
