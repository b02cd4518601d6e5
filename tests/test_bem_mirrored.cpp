// boundary = "mirrored" of the BEM method (app/mirrored_boundary.hpp, docs/solvers.md "Mirrored boundary"):
// the stage solves the periodic even extension of a non-periodic patch and judges the original patch.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "contactbench/app/mirrored_boundary.hpp"
#include "contactbench/app/stages.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench {
namespace {

constexpr Real kModulus = 1e11;  // E* [Pa]
constexpr Index kPatch = 48;     // points a side of the patch (its extension: 96)

BemStage mirrored_stage(bool mirrored) {
  BemStage stage;
  stage.settings = default_settings(bem_settings());
  stage.settings.solver.tolerance = 1e-10;
  stage.settings.mirrored = mirrored;
  stage.periodic = false;
  return stage;
}

// A patch cut out of a periodic surface (not periodic itself: its opposite edges do not meet).
Surface patch_of_periodic_surface() {
  const Index n = 2 * kPatch;
  const Real pixel = 1e-6;
  const Grid grid{.nx = n, .ny = n, .lx = n * pixel, .ly = n * pixel, .periodic = true};
  const SelfAffinePsd psd{
      .sigma = 0.5e-6, .hurst = 0.7, .qr = 4 * 2 * std::numbers::pi / grid.lx, .qs = {}, .anisotropy = 1};
  const Surface large = generate_surface(grid, psd, 40);
  HeightMap patch = large.heights().block(11, 7, kPatch, kPatch);
  return Surface(
      Grid{.nx = kPatch, .ny = kPatch, .lx = kPatch * pixel, .ly = kPatch * pixel, .periodic = false}, patch);
}

// The mirrored stage is the periodic solve of the 2n x 2n even extension, built here node by node (not by
// mirrored_surface), judged on its first quadrant.
TEST(BemMirrored, IsThePeriodicSolveOfTheEvenExtensionJudgedOnThePatch) {
  const Surface patch = patch_of_periodic_surface();
  const Index n = kPatch;
  HeightMap extended(2 * n, 2 * n);
  for (Index i = 0; i < 2 * n; ++i)
    for (Index j = 0; j < 2 * n; ++j)
      extended(i, j) = patch.heights()(i < n ? i : 2 * n - 1 - i, j < n ? j : 2 * n - 1 - j);
  const Surface periodic(
      Grid{.nx = 2 * n, .ny = 2 * n, .lx = 2 * patch.grid().lx, .ly = 2 * patch.grid().ly, .periodic = true},
      extended);
  const Real load = 0.02 * kModulus;
  BemSolver direct(periodic, kModulus, {.tolerance = 1e-10});
  const ContactSolution& truth = direct.solve(load);
  ASSERT_TRUE(truth.converged);

  const BemProducts products =
      run_bem_stage(mirrored_stage(true), SceneSurface(patch), kModulus, {load}, {4}, {});
  ASSERT_EQ(products.solutions.size(), 1u);
  EXPECT_TRUE(products.solutions[0].converged);
  EXPECT_EQ(products.points, n * n);  // the patch is what is judged
  const ContactStatistics& s = products.statistics.at(4)[0];

  const auto quadrant_pressure = truth.pressure.block(0, 0, n, n);
  const Index quadrant_contact = (quadrant_pressure > 0).count();
  // The same problem on the same grid with the same solver: the contact set on the patch is the direct
  // solve's first quadrant, node for node.
  EXPECT_EQ(products.solutions[0].contact_points, quadrant_contact);
  EXPECT_DOUBLE_EQ(s.area_fraction, static_cast<Real>(quadrant_contact) / static_cast<Real>(n * n));
  // The extension is symmetric, so its solution is: the whole contact set is 4 times the quadrant's. A node
  // whose pressure is round-off away from 0 could fall either side of the reflection: allowed 4 such nodes
  // (the solve has none here; the margin is for another FFT library's round-off).
  EXPECT_NEAR(static_cast<Real>(truth.contact_points), 4.0 * static_cast<Real>(quadrant_contact), 4.0);
  // Mean gap on the patch: the quadrant's, to round-off of a mean of 2304 gaps (1e-12 of the gap scale).
  EXPECT_NEAR(s.mean_gap, truth.gap.block(0, 0, n, n).mean(), 1e-12 * truth.gap.abs().maxCoeff());
  // The mean pressure on the patch is the load's: by symmetry every quadrant carries a quarter, to the
  // solver's relative tolerance of the pressure (1e-10; allowed 1e-8).
  EXPECT_NEAR(products.solutions[0].mean_pressure / load, 1.0, 1e-8);
  // The patch judged by itself, its edges not periodic: the edge shares are reported
  // (bem/contact_statistics).
  EXPECT_FALSE(std::isnan(s.edge_contact_share));
}

// A flat patch in full contact: pressed as it is, its edges act like a flat punch's (the pressure peaks at
// the rim, Boussinesq's 1/sqrt singularity on the grid); mirrored, the extension is a flat periodic surface,
// pressed uniformly.
TEST(BemMirrored, FlatPatchInFullContactHasUniformPressureWithoutTheEdgePunch) {
  const Index n = 64;  // more than twice the 20-pixel edge ring, so that the edge shares are defined
  const Real pixel = 1e-6;
  const Surface flat(Grid{.nx = n, .ny = n, .lx = n * pixel, .ly = n * pixel, .periodic = false},
                     HeightMap::Zero(n, n));
  const Real load = 0.01 * kModulus;
  const BemProducts mirrored =
      run_bem_stage(mirrored_stage(true), SceneSurface(flat), kModulus, {load}, {4}, {});
  const BemProducts as_is =
      run_bem_stage(mirrored_stage(false), SceneSurface(flat), kModulus, {load}, {4}, {});
  const ContactStatistics& m = mirrored.statistics.at(4)[0];
  const ContactStatistics& a = as_is.statistics.at(4)[0];
  EXPECT_EQ(m.area_fraction, 1.0);
  // Uniform: the largest pressure is the mean, to the solver's tolerance (1e-10; allowed 1e-8).
  EXPECT_NEAR(m.max_pressure / load, 1.0, 1e-8);
  // The outer 20-pixel ring is 1 - (24/64)^2 = 85.9 % of the nodes and carries that share of the load.
  const Real ring_share = 1.0 - std::pow(24.0 / 64.0, 2);
  EXPECT_NEAR(m.edge_load_share, ring_share, 1e-8);
  // As it is: the rim is a punch's. Its corner pressure is several times the mean (a factor above 2 is far
  // from the uniform 1 and far below the grid's corner value), and the ring carries more than its share.
  EXPECT_GT(a.max_pressure / load, 2.0);
  EXPECT_GT(a.edge_load_share, ring_share + 0.02);
}

// `contactbench bem --boundary`: refused, naming the key, on a periodic problem and for a value it does not
// know; accepted once the periodic surface is taken as a finite record (--non-periodic).
TEST(BemMirrored, TheCommandRefusesMirroringAPeriodicProblemNamingTheKey) {
  const auto folder = std::filesystem::temp_directory_path() / "contactbench_bem_mirrored_cli";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const Index n = 32;
  const Grid grid{.nx = n, .ny = n, .lx = n * 1e-6, .ly = n * 1e-6, .periodic = true};
  const SelfAffinePsd psd{
      .sigma = 0.5e-6, .hurst = 0.7, .qr = 4 * 2 * std::numbers::pi / grid.lx, .qs = {}, .anisotropy = 1};
  const auto surface = folder / "s.txt";
  write_surface(surface.string(), generate_surface(grid, psd, 41));
  const auto bem = [&](const std::string& arguments) {
    const auto err = folder / "stderr.txt";
    const std::string command = std::string(CB_CLI_PATH) + " bem " + surface.string() + " " + arguments +
                                " >/dev/null 2>" + err.string() + " </dev/null";
    const int raw = std::system(command.c_str());
    std::ifstream in(err);
    std::stringstream text;
    text << in.rdbuf();
    return std::pair<int, std::string>{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
  };
  const auto [periodic_status, periodic_err] = bem("--loads 0.01 --boundary mirrored");
  EXPECT_NE(periodic_status, 0);
  EXPECT_NE(periodic_err.find("boundary"), std::string::npos) << periodic_err;
  EXPECT_NE(periodic_err.find("periodic = false"), std::string::npos) << periodic_err;
  const auto [unknown_status, unknown_err] = bem("--loads 0.01 --non-periodic --boundary reflected");
  EXPECT_NE(unknown_status, 0);
  EXPECT_NE(unknown_err.find("boundary"), std::string::npos) << unknown_err;
  const auto [record_status, record_err] = bem("--loads 0.01 --non-periodic --boundary mirrored");
  EXPECT_EQ(record_status, 0) << record_err;
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace contactbench
