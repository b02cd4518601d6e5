// Every check before any work (app/scene_run.hpp): scenes that a method cannot answer are refused after the
// inputs (the surface and its moments) and before the first sweep, solve or theory, with every problem at
// its key path; a method registered by a program runs like a built-in one; separations of every method are
// measured from the mean plane of the heights.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "contactbench/app/methods/method.hpp"
#include "contactbench/app/methods/registry.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_keys.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/topography_io.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

const std::string& kSurface = kSmallSurfaceAndMaterial;

struct Refusal {
  std::vector<std::string> problems;
  std::vector<std::string> stages_started;
};

// Runs the scene, expecting a refusal; records every stage the run started.
Refusal refusal_of(const std::string& text) {
  Refusal refusal;
  RunObserver observer;
  observer.stage_started = [&](const std::string& stage) { refusal.stages_started.push_back(stage); };
  try {
    run_scene(parse_scene(text, "preflight.toml"), {.threads = 1, .observer = &observer});
    ADD_FAILURE() << "the scene ran:\n" << text;
  } catch (const SceneError& error) {
    refusal.problems = error.problems();
  }
  return refusal;
}

// Only the inputs ran: the surface and its moments, no sweep, no BEM, no method's evaluation.
void expect_nothing_but_the_inputs(const Refusal& refusal) {
  EXPECT_EQ(refusal.stages_started, (std::vector<std::string>{"surface", "moments"}));
}

bool has_problem(const Refusal& refusal, const std::string& key_path, const std::string& words) {
  return std::any_of(refusal.problems.begin(), refusal.problems.end(), [&](const std::string& p) {
    return p.find(": " + key_path + ": ") != std::string::npos && p.find(words) != std::string::npos;
  });
}

std::string all(const Refusal& refusal) {
  std::string text;
  for (const auto& p : refusal.problems)
    text += p + "\n";
  return text;
}

TEST(Preflight, ATheoryThatRefusesTheSurfaceStopsTheSceneBeforeTheBem) {
  std::string text = "name = \"anisotropic\"\n" + kSurface + "[loads]\nvalues = [1e-3, 1e-2]\n" +
                     "[methods.bem]\n[methods.gw_mccool]\n[methods.persson]\nanisotropy = \"average\"\n";
  text.replace(text.find("seed = 2 }"), 10, "seed = 2, anisotropy = 2 }");
  const Refusal refusal = refusal_of(text);
  expect_nothing_but_the_inputs(refusal);
  ASSERT_EQ(refusal.problems.size(), 1u) << all(refusal);  // persson averages: it has no problem
  EXPECT_TRUE(has_problem(refusal, "methods.gw_mccool.anisotropy", "anisotropic")) << all(refusal);
  EXPECT_NE(refusal.problems[0].find("accepted: anisotropy = \"average\""), std::string::npos);
}

TEST(Preflight, AHardnessAtOrBelowALoadStopsTheSceneBeforeTheBem) {
  // E* = 109.9 GPa: the loads 1e-3 and 1e-2 are mean pressures of 0.11 and 1.1 GPa; the cap is 0.5 GPa.
  const Refusal refusal = refusal_of("name = \"capped\"\n" + kSurface + "[loads]\nvalues = [1e-3, 1e-2]\n" +
                                     "[interface]\nhardness = 5e8\n" +
                                     "[methods.plateau]\nignore = [\"hardness\"]\n[methods.bem]\n");
  expect_nothing_but_the_inputs(refusal);
  ASSERT_EQ(refusal.problems.size(), 1u) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "interface.hardness", "0.01 (load 2)")) << all(refusal);
  EXPECT_EQ(refusal.problems[0].find("0.001 (load 1)"), std::string::npos) << "the load below H is fine";
}

// Effects belong to the scene (app/interface.hpp): a method that does not model one is refused, naming the
// method and the effect, unless its table ignores it; an ignore of an effect the scene lacks is a mistake.
TEST(Preflight, AnEffectAMethodDoesNotModelIsRefusedNamingBoth) {
  const Refusal refusal = refusal_of("name = \"plastic\"\n" + kSurface + "[interface]\nhardness = 2e9\n" +
                                     "[loads]\nvalues = [1e-3]\n[methods.bem]\n[methods.persson]\n");
  expect_nothing_but_the_inputs(refusal);
  ASSERT_EQ(refusal.problems.size(), 1u) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "methods.persson", "persson does not model the interface's hardness"))
      << all(refusal);
  EXPECT_NE(refusal.problems[0].find("ignore = [\"hardness\"]"), std::string::npos) << all(refusal);
}

// Adhesion is an effect as the hardness is: the theories do not model it yet and are refused unless they
// ignore it; the BEM models it, but not together with a hardness.
TEST(Preflight, AdhesionIsRefusedWhereItIsNotModelled) {
  const std::string adhesion = "[interface]\nadhesion = { model = \"dugdale\", work = 0.05, stress = 1e6 }\n";
  const Refusal refused = refusal_of("name = \"sticky\"\n" + kSurface + adhesion +
                                     "[loads]\nvalues = [1e-3]\n[methods.bem]\n[methods.persson]\n");
  expect_nothing_but_the_inputs(refused);
  ASSERT_EQ(refused.problems.size(), 1u) << all(refused);
  EXPECT_TRUE(has_problem(refused, "methods.persson", "persson does not model the interface's adhesion"))
      << all(refused);
  const Refusal both = refusal_of("name = \"sticky_plastic\"\n" + kSurface + adhesion + "hardness = 5e9\n" +
                                  "[loads]\nvalues = [1e-3]\n[methods.bem]\n");
  expect_nothing_but_the_inputs(both);
  ASSERT_EQ(both.problems.size(), 1u) << all(both);
  EXPECT_TRUE(has_problem(both, "interface.adhesion", "adhesion and a hardness together")) << all(both);
}

// The adhesive solver that minimises the exponential law's energy (docs/theory.md 10.11) is refused by name
// for the Dugdale law (a kink in its potential) and for the non-periodic problem (no stiffness operator).
TEST(Preflight, AnAdhesiveSolverThatCannotTakeTheLawIsRefusedByName) {
  const Refusal dugdale =
      refusal_of("name = \"sticky\"\n" + kSurface +
                 "[interface]\nadhesion = { model = \"dugdale\", work = 0.05, stress = 1e6 }\n" +
                 "[loads]\nvalues = [1e-3]\n[methods.bem]\nadhesive_solver = \"projected_lbfgs\"\n");
  expect_nothing_but_the_inputs(dugdale);
  ASSERT_EQ(dugdale.problems.size(), 1u) << all(dugdale);
  EXPECT_TRUE(has_problem(dugdale, "methods.bem.adhesive_solver", "dugdale law's potential has a kink"))
      << all(dugdale);
  const Refusal edges =
      refusal_of("name = \"sticky\"\n" + kSurface +
                 "[interface]\nadhesion = { model = \"exponential\", work = 0.05, range = 1e-6 }\n" +
                 "[loads]\nvalues = [1e-3]\n[methods.bem]\nadhesive_solver = \"projected_lbfgs\"\n"
                 "periodic = false\n");
  expect_nothing_but_the_inputs(edges);
  ASSERT_EQ(edges.problems.size(), 1u) << all(edges);
  EXPECT_TRUE(has_problem(edges, "methods.bem.adhesive_solver", "periodic problem only")) << all(edges);
  // The whole-surface CG moves the Dugdale law's zone: with the exponential law it is refused, not run as the
  // fixed point.
  const Refusal smooth =
      refusal_of("name = \"sticky\"\n" + kSurface +
                 "[interface]\nadhesion = { model = \"exponential\", work = 0.05, range = 1e-6 }\n" +
                 "[loads]\nvalues = [1e-3]\n[methods.bem]\nadhesive_solver = \"constrained_cg\"\n");
  expect_nothing_but_the_inputs(smooth);
  ASSERT_EQ(smooth.problems.size(), 1u) << all(smooth);
  EXPECT_TRUE(has_problem(smooth, "methods.bem.adhesive_solver", "exponential law has no such zone"))
      << all(smooth);
}

TEST(Preflight, IgnoringAnEffectTheSceneLacksIsRefused) {
  const Refusal refusal = refusal_of("name = \"elastic\"\n" + kSurface + "[loads]\nvalues = [1e-3]\n" +
                                     "[methods.persson]\nignore = [\"hardness\"]\n");
  expect_nothing_but_the_inputs(refusal);
  ASSERT_EQ(refusal.problems.size(), 1u) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "methods.persson.ignore", "does not call for")) << all(refusal);
}

TEST(Preflight, LoadsATheoryRefusesStopTheSceneBeforeTheBem) {
  // BGT reaches P/(E* A0) of about 0.1 at its lowest separation (-5 sqrt(m0)): 5 is beyond it.
  const Refusal refusal = refusal_of("name = \"too_heavy\"\n" + kSurface + "[loads]\nvalues = [1e-3, 5]\n" +
                                     "[methods.bem]\n[methods.bgt]\n[methods.persson]\n");
  expect_nothing_but_the_inputs(refusal);
  ASSERT_EQ(refusal.problems.size(), 1u) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "methods.bgt", "the load P/(E* A0) = 5 is beyond")) << all(refusal);
}

TEST(Preflight, EveryProblemOfEveryMethodIsListedAtOnce) {
  std::string text = "name = \"everything\"\n" + kSurface + "[interface]\nhardness = 5e8\n" +
                     "[loads]\nvalues = [1e-3, 5]\n" +
                     "[methods.bem]\n[methods.gw_mccool]\nignore = [\"hardness\"]\n[methods.bgt]\n"
                     "anisotropy = \"average\"\nignore = [\"hardness\"]\n";
  text.replace(text.find("seed = 2 }"), 10, "seed = 2, anisotropy = 2 }");
  const Refusal refusal = refusal_of(text);
  expect_nothing_but_the_inputs(refusal);
  EXPECT_EQ(refusal.problems.size(), 3u) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "interface.hardness", "full plastic contact")) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "methods.gw_mccool.anisotropy", "anisotropic")) << all(refusal);
  EXPECT_TRUE(has_problem(refusal, "methods.bgt", "= 5 is beyond")) << all(refusal);
}

// A method added by a program: one class and one registration. It answers A/A0 = load (a made-up law), needs
// nothing but the moments, and refuses loads above 1 in its preflight.
class ProportionalMethod final : public Method {
 public:
  std::string_view name() const override { return "proportional"; }
  std::string compared_area() const override { return "A/A0 = load"; }
  void read(const Section&, const SceneContext&) override {}
  void write(SceneKeys&) const override {}
  MethodNeeds needs(const SceneContext&) const override { return {.moments = true}; }
  void preflight(const MethodCheck& check) const override {
    if (check.scene.loads.back() > 1) check.problem("", "a load above 1", "loads <= 1");
  }
  MethodCurve evaluate(const MethodInputs& in) const override {
    MethodCurve curve;
    curve.area_fraction = in.scene.loads;
    curve.separation = curve.spots = std::vector<Real>(in.scene.loads.size(), std::nan(""));
    return curve;
  }
};

TEST(MethodRegistry, AMethodAddedByAProgramRunsLikeABuiltInOne) {
  MethodRegistry& registry = MethodRegistry::global();
  registry.add("proportional", [] { return std::make_unique<ProportionalMethod>(); });
  const std::string scene = "name = \"added\"\n" + kSurface + "[methods.mine]\nmethod = \"proportional\"\n";
  const SceneReport report =
      run_scene(parse_scene(scene + "[loads]\nvalues = [1e-3, 1e-2]\n", "added.toml"), {.threads = 1});
  ASSERT_EQ(report.methods.size(), 1u);
  EXPECT_EQ(report.methods[0].method, "proportional");
  EXPECT_EQ(report.methods[0].curve.area_fraction, report.loads());
  const Refusal refused = refusal_of(scene + "[loads]\nvalues = [1e-3, 2]\n");
  EXPECT_TRUE(has_problem(refused, "methods.mine", "a load above 1")) << all(refused);
  registry.remove("proportional");
  try {
    parse_scene(scene + "[loads]\nvalues = [1e-3]\n", "added.toml");
    ADD_FAILURE() << "a removed method was found";
  } catch (const SceneError& error) {
    // An unknown name lists the known ones.
    EXPECT_NE(std::string(error.what()).find("unknown method \"proportional\"; accepted: bem, plateau"),
              std::string::npos)
        << error.what();
  }
}

// A measured surface whose heights do not average to zero: the plateau model and the BEM measure their
// separations from the same plane, the mean plane of the heights, so shifting the file's heights changes
// neither, and at a small load (the flat near the highest point) the two agree on where that point is.
TEST(Separation, PlateauAndBemMeasureFromTheMeanPlane) {
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "contactbench_mean_plane";
  std::filesystem::create_directories(folder);
  const Grid grid{.nx = 32, .ny = 32, .lx = 100e-6, .ly = 100e-6, .periodic = true};
  const Real sigma = 0.5e-6;
  const Surface surface =
      generate_surface(grid, {.sigma = sigma, .hurst = 0.7, .qr = 2 * 3.14e4, .qs = std::nullopt}, 3);
  const Real offset = 20 * sigma;  // far more than any separation of the curve
  write_surface(folder / "centred.txt", surface);
  write_surface(folder / "shifted.txt", Surface(grid, surface.heights() + offset));
  const auto run_on = [&](const std::string& file) {
    return run_scene(parse_scene("name = \"mean\"\n[surface]\nfile = \"" + (folder / file).string() +
                                     "\"\n[material]\nestar = 1e11\n[loads]\nvalues = [1e-5, 1e-3]\n"
                                     "[methods.bem]\ntolerance = 1e-10\n[methods.plateau]\n",
                                 folder / "scene.toml"),
                     {.threads = 1});
  };
  const SceneReport centred = run_on("centred.txt"), shifted = run_on("shifted.txt");
  const Real highest = surface.heights().maxCoeff() - surface.mean_height();
  for (std::size_t m = 0; m < 2; ++m)
    for (std::size_t k = 0; k < 2; ++k) {
      const Real a = centred.methods[m].curve.separation[k], b = shifted.methods[m].curve.separation[k];
      // The BEM solves a shifted copy of the same heights: its separations agree to its tolerance's effect on
      // the flat's height (1e-10 relative pressure change: far below 1e-6 sigma); the sweep's exactly but for
      // the round-off of subtracting the mean (1e-15 sigma).
      EXPECT_NEAR(a, b, 1e-6 * sigma) << centred.methods[m].label << " at load " << k;
      EXPECT_LT(b, highest) << "below the highest point";
    }
  // At P/(E* A0) = 1e-5 both models have the flat near the highest point (2.36 sigma above the mean plane;
  // measured: the BEM at 2.29 sigma, the plateau model at 2.30): they agree to a tenth of sigma, where
  // measured from different planes they would be 20 sigma apart.
  EXPECT_NEAR(shifted.methods[0].curve.separation[0], shifted.methods[1].curve.separation[0], 0.1 * sigma);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace contactbench
