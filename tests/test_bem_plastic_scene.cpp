// A scene's load path through the plastic BEM, end to end (scenes/README.md, [loads] path; docs/solvers.md
// "Hardness", "Unloading and reloading"): the path is read and written back, the BEM solves it in order and
// reports every step (MethodCurve::path_columns, <label>_path.csv) and each scene load once, the residual
// topography it writes is a surface `run` reads, and what cannot be solved is refused before any stage.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/topography_io.hpp"
#include "run_scene_text.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

const std::vector<Real>& column(const std::vector<std::pair<std::string, std::vector<Real>>>& columns,
                                const std::string& name) {
  const auto found =
      std::find_if(columns.begin(), columns.end(), [&](const auto& c) { return c.first == name; });
  if (found == columns.end()) throw std::runtime_error("no column " + name);
  return found->second;
}

// Surface A on 32^2 (small_scene.hpp), H = 6 GPa: at P/(E* A0) = 4e-3 part of the contact is plastic.
const std::string kPath = R"(
[interface]
hardness = 6e9
[loads]
values = [1e-3, 4e-3, 1e-3, 4e-3]
path = "as listed"
)";

TEST(PlasticPath, IsReadInOrderAndWrittenBack) {
  const Scene scene =
      parse_scene("name = \"p\"\n" + kSmallSurfaceAndMaterial + kPath + "[methods.bem]\n", "test.toml");
  EXPECT_EQ(scene.loads, (std::vector<Real>{1e-3, 4e-3}));  // every method answers at each load once
  EXPECT_EQ(scene.load_path, (std::vector<Real>{1e-3, 4e-3, 1e-3, 4e-3}));
  const Scene again = parse_scene(to_toml(scene), "again.toml");
  EXPECT_EQ(again.load_path, scene.load_path);
  // The default stays: sorted, each once, no path.
  const Scene sorted = parse_scene(
      "name = \"s\"\n" + kSmallSurfaceAndMaterial + "[loads]\nvalues = [4e-3, 1e-3, 4e-3]\n[methods.bem]\n",
      "test.toml");
  EXPECT_EQ(sorted.loads, (std::vector<Real>{1e-3, 4e-3}));
  EXPECT_TRUE(sorted.load_path.empty());
  try {
    parse_scene("name = \"u\"\n" + kSmallSurfaceAndMaterial +
                    "[loads]\nvalues = [1e-3]\npath = \"up and down\"\n[methods.bem]\n",
                "test.toml");
    ADD_FAILURE() << "an unknown path was accepted";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("loads.path"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("as listed"), std::string::npos) << e.what();
  }
}

TEST(PlasticPath, TheBemReportsEveryStepAndShakesDown) {
  const fs::path folder = fs::temp_directory_path() / "cb_plastic_path";
  fs::remove_all(folder);
  fs::create_directories(folder);
  const SceneReport report =
      run_scene_text("name = \"p\"\nreference = \"\"\n" + kSmallSurfaceAndMaterial + kPath +
                         "[methods.bem]\ntolerance = 1e-10\nresidual_topography = \"residual.txt\"\n",
                     folder / "scene.toml");
  const MethodCurve& curve = report.methods.at(0).curve;
  const auto& path = curve.path_columns;
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(column(path, "direction"), (std::vector<Real>{1, 1, -1, 1}));
  const std::vector<Real>& area = column(path, "area_fraction");
  const std::vector<Real>& plastic = column(path, "plastic_area_fraction");
  ASSERT_EQ(area.size(), 4u);
  EXPECT_GT(plastic[1], 0);     // the top load flows
  EXPECT_EQ(plastic[2], 0);     // unloading is elastic
  EXPECT_GT(area[2], area[0]);  // the flattened summits meet more area on unloading
  // Reloading to the top gives its area back: the same state, up to edge nodes whose pressure is within the
  // tolerance of zero (measured: identical counts on this grid); allow one node of 32^2.
  EXPECT_NEAR(area[3], area[1], 1.0 / (32 * 32));
  // curves.csv's rows: each scene load at the first step that reached it.
  EXPECT_EQ(column(curve.columns, "path_step"), (std::vector<Real>{1, 2}));
  EXPECT_EQ(curve.area_fraction[0], area[0]);
  EXPECT_EQ(curve.area_fraction[1], area[1]);
  // plastic_load_fraction = H x plastic area / load, each plastic node carrying H (exact up to round-off).
  const Real estar = report.scene.material.estar;
  EXPECT_NEAR(column(path, "plastic_load_fraction")[1], 6e9 * plastic[1] / (4e-3 * estar), 1e-12);
  // The report writes the steps as bem_path.csv.
  write_report(folder / "out", report, compare(report), Provenance{});
  EXPECT_TRUE(fs::exists(folder / "out" / "bem_path.csv"));
  // The residual topography: a surface file the project reads (what `stats` and `run` use), lower than
  // the given surface nowhere above it; a scene on it runs.
  const Surface residual = read_topography(folder / "residual.txt");
  EXPECT_EQ(residual.grid().nx, 32);
  const SceneReport on_residual = run_scene_text(
      "name = \"r\"\nreference = \"\"\n[surface]\nfile = \"residual.txt\"\n[material]\nE = 100e9\nnu = "
      "0.3\n[loads]\nvalues = [1e-3]\n[methods.bem]\n",
      folder / "again.toml");
  EXPECT_GT(on_residual.methods.at(0).curve.area_fraction[0], 0);
  fs::remove_all(folder);
}

TEST(PlasticPath, RefusesWhatItCannotSolveBeforeAnyStage) {
  const auto problems = [](const std::string& text) {
    try {
      run_scene_text(text);
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  // A residual topography without a load path: the surface never changes.
  const std::string no_path = problems("name = \"n\"\n" + kSmallSurfaceAndMaterial +
                                       "[interface]\nhardness = 6e9\n[loads]\nvalues = [1e-3]\n"
                                       "[methods.bem]\nresidual_topography = \"r.txt\"\n");
  EXPECT_NE(no_path.find("residual_topography"), std::string::npos) << no_path;
  EXPECT_NE(no_path.find("no load path"), std::string::npos) << no_path;
  // A hardness at or below a load's mean pressure, named by the load (full plastic contact).
  const std::string full = problems("name = \"f\"\n" + kSmallSurfaceAndMaterial +
                                    "[interface]\nhardness = 2e8\n[loads]\nvalues = [1e-3, 4e-3, 1e-3]\n"
                                    "path = \"as listed\"\n[methods.bem]\n");
  EXPECT_NE(full.find("interface.hardness"), std::string::npos) << full;
  EXPECT_NE(full.find("0.004 (load 2)"), std::string::npos) << full;
  // The extrapolated area along a path.
  const std::string extrapolate =
      problems("name = \"e\"\n" + kSmallSurfaceAndMaterial + kPath + "[methods.bem]\nextrapolate = true\n");
  EXPECT_NE(extrapolate.find("extrapolate"), std::string::npos) << extrapolate;
}

}  // namespace
}  // namespace contactbench
