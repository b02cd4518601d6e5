// The distributions at a scene's reference load (app/distributions_csv.hpp; issue 36): each histogram's
// integrals are the quantities it comes from, nothing is measured when the scene does not ask, and a load
// that is not one of the scene's is refused naming the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>

#include "contactbench/app/comparison.hpp"
#include "contactbench/app/distributions_csv.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/scene_run.hpp"
#include "run_scene_text.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

const std::string kLoads = "[loads]\nvalues = [1e-3, 1e-2, 3e-2]\n";

std::string scene_with(const std::string& distributions) {
  return "name = \"distributions\"\n" + distributions + kSmallSurfaceAndMaterial + kLoads + "[methods.bem]\n";
}

// sum over bins of f(centre) * density * width
template <class F>
Real moment(const Histogram& h, F f) {
  Real sum = 0;
  for (std::size_t i = 0; i < h.counts.size(); ++i)
    sum += f(h.centre(i)) * h.density[i] * h.width(i);
  return sum;
}

TEST(Distributions, IntegralsAreTheQuantitiesTheyComeFrom) {
  const SceneReport report = run_scene_text(scene_with("distributions = { load = 1e-2, bins = 40 }\n"));
  const MethodCurve& curve = report.methods.front().curve;
  ASSERT_TRUE(curve.distributions.has_value());
  const LoadDistributions& d = *curve.distributions;
  ASSERT_GT(d.contact_points, 10);  // enough contact for the histograms to mean something
  const Real area = static_cast<Real>(d.contact_points) / static_cast<Real>(d.points);
  // The node count the statistics report at the same load (the 2nd scene load): the same contact set.
  EXPECT_DOUBLE_EQ(area, curve.area_fraction_nodes[1]);

  // int P(sigma) dsigma = A/A0: a sum of counts / N, exact but for the rounding of ~40 products and sums,
  // so 1e-12 relative.
  EXPECT_NEAR(moment(d.pressure, [](Real) { return 1; }), area, 1e-12 * area);
  EXPECT_EQ(std::accumulate(d.pressure.counts.begin(), d.pressure.counts.end(), Index(0)), d.contact_points);
  // First moment = mean pressure: each node's pressure is within half a bin of its bin's centre, so the
  // sum is off by at most (width/2) A/A0 (plus rounding, 1e-12 of the mean).
  const Real half_bin = d.pressure.width(0) / 2;
  EXPECT_NEAR(moment(d.pressure, [](Real s) { return s; }), d.mean_pressure,
              half_bin * area + 1e-12 * d.mean_pressure);
  // and the mean pressure is the load (no attraction here), to the solver's tolerance 1e-8 of its default.
  EXPECT_NEAR(d.mean_pressure / d.estar, 1e-2, 1e-6 * 1e-2);

  // Gap: int P(g) dg = 1 - A/A0 (counts again: 1e-12); int g P(g) dg = u-bar over the whole surface, within
  // (width/2)(1 - A/A0) (the contact nodes' gap is 0, the delta the histogram leaves out).
  EXPECT_NEAR(moment(d.gap, [](Real) { return 1; }), 1 - area, 1e-12);
  const Real half_gap_bin = d.gap.width(0) / 2;
  EXPECT_NEAR(moment(d.gap, [](Real g) { return g; }), d.mean_gap,
              half_gap_bin * (1 - area) + 1e-12 * d.mean_gap);
  // and the bins are not so wide that the check above is empty: the bound is under 10 % of u-bar.
  EXPECT_LT(half_gap_bin * (1 - area), 0.1 * d.mean_gap);

  // Patch sizes: one count per cluster, as many as the spots the method reports at that load.
  EXPECT_EQ(std::accumulate(d.patch_sizes.counts.begin(), d.patch_sizes.counts.end(), Index(0)),
            static_cast<Index>(curve.spots[1]));
}

TEST(Distributions, PatchSizeBinsHoldEachSizeOnce) {
  // Sizes 1, 1, 2, 7, 100 on 4 logarithmic bins from 1 to 101: r = 101^(1/4) ~ 3.17, edges 1, 3.17, 10.05,
  // 31.9, 101; exact counts, so exact comparisons.
  const Histogram h = patch_size_histogram({1, 1, 2, 7, 100}, 4);
  ASSERT_EQ(h.counts.size(), 4u);
  EXPECT_EQ(h.counts, (std::vector<Index>{3, 1, 0, 1}));
  EXPECT_EQ(h.edges.front(), 1);
  EXPECT_EQ(h.edges.back(), 101);
}

TEST(Distributions, NothingMeasuredWhenTheSceneDoesNotAsk) {
  const SceneReport report = run_scene_text(scene_with(""));
  EXPECT_FALSE(report.methods.front().curve.distributions.has_value());
  for (const StageRecord& stage : report.stages)
    EXPECT_EQ(stage.name.find("distributions"), std::string::npos) << stage.name;
}

TEST(Distributions, ALoadNotInTheSceneIsRefusedNamingTheKey) {
  try {
    parse_scene(scene_with("distributions = { load = 2e-2 }\n"), "test.toml");
    FAIL() << "a load that is not one of the scene's was accepted";
  } catch (const SceneError& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("distributions.load"), std::string::npos) << text;
    EXPECT_NE(text.find("0.01"), std::string::npos) << text;  // lists the loads accepted
  }
  try {
    parse_scene("name = \"x\"\ndistributions = { load = 1e-2 }\n" + kSmallSurfaceAndMaterial + kLoads +
                    "[methods.persson]\n",
                "test.toml");
    FAIL() << "distributions without a BEM were accepted";
  } catch (const SceneError& error) {
    EXPECT_NE(std::string(error.what()).find("no bem method"), std::string::npos) << error.what();
  }
}

TEST(Distributions, WrittenStampedAndReadBack) {
  const Scene scene = parse_scene(scene_with("distributions = { load = 3e-2, bins = 12 }\n"), "test.toml");
  // The key survives the scene's round trip through its TOML.
  const Scene again = parse_scene(to_toml(scene), "again.toml");
  ASSERT_TRUE(again.distributions.has_value());
  EXPECT_EQ(again.distributions->load, 3e-2);
  EXPECT_EQ(again.distributions->bins, 12);
  const SceneReport report = run_scene(scene, {.threads = 1, .observer = nullptr});
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "contactbench_distributions";
  std::filesystem::remove_all(folder);
  write_report(folder, report, compare(report), current_provenance(1, "contactbench run test.toml"));
  for (const char* name :
       {"bem_pressure_distribution.csv", "bem_gap_distribution.csv", "bem_patch_sizes.csv"}) {
    std::ifstream in(folder / name);
    ASSERT_TRUE(in) << name;
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line.rfind("# contactbench run of scene distributions, bem (commit ", 0), 0u) << line;
    EXPECT_NE(line.find("contactbench run test.toml"), std::string::npos) << line;
    std::size_t rows = 0;
    while (std::getline(in, line))
      if (!line.empty() && line[0] != '#') ++rows;
    EXPECT_EQ(rows, 13u) << name;  // the header row and 12 bins
  }
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace contactbench
