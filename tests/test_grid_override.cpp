// `contactbench run SCENE --grid N` (app/scene_grid_override.hpp, scenes/README.md "Running a scene"): the
// scene's generated surface on N points a side, every refine key scaled alike, refused with the key named
// where it cannot apply, and recorded in the run's summary.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <variant>

#include <toml++/toml.h>

#include "cli_runner.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_toml.hpp"
#include "contactbench/core/grid.hpp"

namespace contactbench {
namespace {

using testing::CommandResult;
using testing::slurp;

class GridOverride : public testing::CliTest {
 protected:
  GridOverride() : CliTest("contactbench_grid_override_") {}

  // Surface A's spectrum on `grid` points over 200 um, with `generate_extra` in its generate table.
  std::filesystem::path scene(const std::string& generate_extra, const std::string& methods,
                              const std::string& name = "grid") {
    return write(name + ".toml",
                 "name = \"" + name +
                     "\"\ndescription = \"A small scene.\"\n[surface]\n"
                     "generate = { sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, size = 200e-6, seed = 1" +
                     generate_extra +
                     " }\n[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-3, 1e-2]\n" + methods);
  }

  // The message of the SceneError read_scene throws, or "" when it reads the scene.
  static std::string refusal(const std::filesystem::path& path, Index grid) {
    try {
      read_scene_on_grid(path, grid);
    } catch (const SceneError& error) {
      return error.what();
    }
    return "";
  }
};

TEST_F(GridOverride, SetsTheGridAndScalesEveryRefineKey) {
  const auto path = scene(", grid = 64, refine = 96",
                          "[methods.bem]\nrefine = 128\nextrapolate = true\n[methods.plateau]\nrefine = 256\n"
                          "[methods.coarse]\nmethod = \"plateau\"\n[methods.persson]\n");
  const Scene scene = read_scene_on_grid(path, Index{32});
  const auto& generated = std::get<GeneratedSurfaceSpec>(scene.surface.source);
  EXPECT_EQ(generated.grid, 32);
  EXPECT_EQ(generated.refine, 48);  // 96 x 32/64
  EXPECT_EQ(generated.seed, 1u);
  EXPECT_EQ(generated.size, 200e-6);
  EXPECT_EQ(generated.sigma, 0.5e-6);
  // qs left out: the new grid's Nyquist wavevector pi N/L (exactly as the parser computes it).
  const Grid lattice{32, 32, 200e-6, 200e-6, true};
  EXPECT_EQ(generated.qs, lattice.nyquist());
  const toml::table understood = toml::parse(to_toml(scene));
  EXPECT_EQ(understood["methods"]["bem"]["refine"].value<std::int64_t>(), 64);       // 128 x 32/64
  EXPECT_EQ(understood["methods"]["plateau"]["refine"].value<std::int64_t>(), 128);  // 256 x 32/64
  EXPECT_EQ(understood["methods"]["coarse"]["refine"].value<std::int64_t>(), 0);     // none: stays none
  const std::string note =
      "Run with --grid 32: the surface generated on 32 x 32 points instead of the scene's "
      "64 x 64 (qs at the new grid's Nyquist wavevector), every refine scaled by 32/64.";
  EXPECT_EQ(scene.description, "A small scene. " + note);

  // A finer look works the same way; a ratio that does not divide rounds to the nearest point, at least N.
  const Scene finer_scene = read_scene_on_grid(path, Index{100});
  const auto& finer = std::get<GeneratedSurfaceSpec>(finer_scene.surface.source);
  EXPECT_EQ(finer.grid, 100);
  EXPECT_EQ(finer.refine, 150);  // 96 x 100/64 = 150
  // Without the override the scene is as written.
  const Scene as_written = read_scene(path);
  EXPECT_EQ(std::get<GeneratedSurfaceSpec>(as_written.surface.source).grid, 64);
}

TEST_F(GridOverride, AStatedQsIsKeptAndATooCoarseGridIsRefusedWithTheLeastThatWorks) {
  const auto path = scene(", grid = 256, qs = 1.0e6", "[methods.persson]\n");
  // pi N / L >= qs needs N >= 1e6 x 200e-6 / pi = 63.66: 64 points a side.
  const Scene scene_64 = read_scene_on_grid(path, Index{64});
  const auto& at_64 = std::get<GeneratedSurfaceSpec>(scene_64.surface.source);
  EXPECT_EQ(at_64.qs, 1.0e6);
  EXPECT_EQ(at_64.grid, 64);
  const std::string message = refusal(path, 63);
  EXPECT_NE(message.find("surface.generate.grid"), std::string::npos) << message;
  EXPECT_NE(message.find("--grid 63 cannot carry"), std::string::npos) << message;
  EXPECT_NE(message.find("--grid 64 or more"), std::string::npos) << message;
  EXPECT_NE(message.find("surface.generate.qs = 1e+06"), std::string::npos) << message;

  // With qs at its default, the grid must put Nyquist above qr: pi N / L > 3.14e4 needs N >= 2 here, so take
  // surface B's qr = 1e5: N > 1e5 x 200e-6 / pi = 6.37, so 7.
  const auto b = write("b.toml",
                       "name = \"b\"\n[surface]\ngenerate = { sigma = 1e-6, hurst = 0.8, qr = 1e5, "
                       "size = 200e-6, grid = 256, seed = 1 }\n[material]\nestar = 1e11\n"
                       "[loads]\nvalues = [1e-3]\n[methods.persson]\n");
  EXPECT_EQ(refusal(b, 7), "");
  const std::string b_message = refusal(b, 6);
  EXPECT_NE(b_message.find("--grid 7 or more"), std::string::npos) << b_message;
  EXPECT_NE(b_message.find("surface.generate.qr = 1e+05"), std::string::npos) << b_message;
}

TEST_F(GridOverride, AFileSurfaceIsRefusedNamingSurfaceFile) {
  write("heights.txt", "0 1e-6 2e-6\n1e-6 0 -1e-6\n-2e-6 1e-6 0\n");
  const auto path = write("file.toml",
                          "name = \"file\"\n[surface]\nfile = \"heights.txt\"\nsize = 3e-6\n"
                          "[material]\nestar = 1e11\n[loads]\nvalues = [1e-3]\n[methods.persson]\n");
  const std::string message = refusal(path, 64);
  EXPECT_NE(
      message.find(path.string() + ":3: surface.file: --grid 64 sets the points of a generated surface"),
      std::string::npos)
      << message;
  EXPECT_NE(message.find("surface.crop"), std::string::npos) << message;
}

TEST_F(GridOverride, ARefineScaledBeyondTheLargestGridIsRefusedNamingIt) {
  const auto path = scene(", grid = 64", "[methods.plateau]\nrefine = 65536\n");
  const std::string message = refusal(path, 128);
  EXPECT_NE(message.find("methods.plateau.refine: --grid 128 scales refine = 65536 to 131072"),
            std::string::npos)
      << message;
}

TEST_F(GridOverride, TheScenesOwnProblemsAreReportedAtTheirLinesFirst) {
  const auto path = scene(", grid = 64, colour = 1", "[methods.persson]\n");
  const std::string message = refusal(path, 32);
  EXPECT_NE(message.find(path.string() + ":4: surface.generate.colour: unknown key"), std::string::npos)
      << message;
}

// Through the program: the override runs, and the outputs record what was typed and what it changed.
TEST_F(GridOverride, RunRecordsTheOverrideAndRefusesWithTheKey) {
  const auto path = scene(", grid = 64", "[methods.bem]\nrefine = 128\n[methods.plateau]\n");
  const auto out = folder_ / "out";
  const std::string typed =
      "run " + path.string() + " --threads 1 --grid 16 --out " + out.string() + " --no-plots";
  const CommandResult result = run(typed + " --quiet");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string summary = slurp(out / "summary.json");
  EXPECT_NE(summary.find("\"command\": \"contactbench " + typed + "\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"grid\": 16,"), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"refine\": 32,"), std::string::npos) << summary;  // the bem's 128 x 16/64
  EXPECT_NE(summary.find("Run with --grid 16: the surface generated on 16 x 16 points"), std::string::npos)
      << summary;
  EXPECT_NE(slurp(out / "table.md").find("--grid 16"), std::string::npos);
  EXPECT_NE(slurp(out / "curves.csv").find("--grid 16"), std::string::npos);  // its stamp line's command

  // Refused before any work, naming the key (a file surface) or the flag's range (fewer than 2 points).
  write("heights.txt", "0 1e-6 2e-6\n1e-6 0 -1e-6\n-2e-6 1e-6 0\n");
  const auto file_scene = write("file.toml",
                                "name = \"file\"\n[surface]\nfile = \"heights.txt\"\nsize = 3e-6\n"
                                "[material]\nestar = 1e11\n[loads]\nvalues = [1e-3]\n[methods.persson]\n");
  const auto refused_out = folder_ / "refused";
  const CommandResult refused =
      run("run " + file_scene.string() + " --grid 64 --out " + refused_out.string());
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("surface.file: --grid 64 sets the points of a generated surface"),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(refused_out));
  const CommandResult too_few = run("run " + path.string() + " --grid 1 --out " + refused_out.string());
  EXPECT_NE(too_few.status, 0);
  EXPECT_NE(too_few.err.find("--grid"), std::string::npos) << too_few.err;
  EXPECT_FALSE(std::filesystem::exists(refused_out));
}

}  // namespace
}  // namespace contactbench
