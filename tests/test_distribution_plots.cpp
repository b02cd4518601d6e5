// Plots of the distributions (app/distribution_plots.hpp): a scene that asks for distributions gets a PNG and
// an SVG of each CSV from `run`, `contactbench plot` draws such a CSV, and a theory column without numbers is
// left out of the plot rather than drawn as zeros.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "cli_runner.hpp"
#include "contactbench/app/distribution_plots.hpp"
#include "contactbench/app/gnuplot_text.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

using testing::slurp;

class DistributionPlots : public testing::CliTest {
 protected:
  DistributionPlots() : CliTest("cb_distplots_") {}
};

const std::string kScene =
    "name = \"dist\"\nreference = \"bem\"\ndistributions = { load = 1e-2, bins = 20 }\n" +
    kSmallSurfaceAndMaterial + "[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\n";

TEST_F(DistributionPlots, TheFilesSayWhatTheyHoldAndEmptyColumnsAreLeftOut) {
  const auto gap =
      write("g.csv",
            "# stamp\n# gap distribution P(g) at load P/(E* A0) = 0.01: text\n"
            "gap_low,gap_high,gap,count,density,plateau_density,plateau_hertz_density,summit_density\n"
            "0,1e-7,5e-8,3,10,2,,4\n1e-7,2e-7,1.5e-7,1,5,1,,3\n");
  const auto file = read_distribution_file(gap);
  ASSERT_TRUE(file.has_value());
  EXPECT_EQ(file->kind, DistributionKind::gap);
  EXPECT_EQ(file->load, "0.01");
  EXPECT_DOUBLE_EQ(file->largest_x, 2e-7);
  std::ostringstream script;
  write_distribution_gnuplot_script(script, *file, gap.string(), "t", "a.png", "");
  const std::string text = script.str();
  EXPECT_NE(text.find("\"summit_density\""), std::string::npos);
  EXPECT_NE(text.find("\"plateau_density\""), std::string::npos);
  EXPECT_EQ(text.find("\"plateau_hertz_density\""), std::string::npos);  // no numbers: not drawn
  EXPECT_NE(text.find("set logscale y"), std::string::npos);
  EXPECT_NE(text.find("gap g [nm]"), std::string::npos);  // 200 nm: read in nm
  // Not a distribution: refused by name.
  EXPECT_FALSE(read_distribution_file(write("x.csv", "a,b\n1,2\n")).has_value());
}

TEST_F(DistributionPlots, RunDrawsThemAndPlotRedrawsOne) {
  const auto scene = write("dist.toml", kScene);
  const auto out = folder_ / "out";
  const auto result = run("run " + scene.string() + " --quiet --out " + out.string());
  ASSERT_EQ(result.status, 0) << result.err;
  for (const char* name : {"bem_pressure_distribution", "bem_gap_distribution", "bem_patch_sizes"}) {
    EXPECT_TRUE(std::filesystem::exists(out / (std::string(name) + ".csv"))) << name;
    if (gnuplot_available()) {
      EXPECT_GT(std::filesystem::file_size(out / (std::string(name) + ".png")), 1000u) << name;
      const std::string svg = slurp(out / (std::string(name) + ".svg"));
      EXPECT_NE(svg.find("</svg>"), std::string::npos) << name;
      EXPECT_NE(svg.find("BEM"), std::string::npos) << name;
    }
  }
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (CI installs gnuplot-nox)";
  const std::string svg = slurp(out / "bem_pressure_distribution.svg");
  EXPECT_NE(svg.find("Persson"), std::string::npos);
  const auto drawn =
      run("plot " + (out / "bem_patch_sizes.csv").string() + " --out " + (folder_ / "p.svg").string());
  ASSERT_EQ(drawn.status, 0) << drawn.err;
  EXPECT_NE(slurp(folder_ / "p.svg").find("BEM clusters"),
            std::string::npos);  // (32^2: too few patches for a fit)
  const auto refused = run("plot " + write("x.csv", "a,b\n1,2\n").string());
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.err.find("not a distribution CSV"), std::string::npos) << refused.err;
}

// A scene without distributions draws none (and costs no gnuplot run for them).
TEST_F(DistributionPlots, NoneWithoutTheKey) {
  const auto scene =
      write("plain.toml", "name = \"plain\"\nreference = \"bem\"\n" + kSmallSurfaceAndMaterial +
                              "[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\n");
  const auto out = folder_ / "out";
  ASSERT_EQ(run("run " + scene.string() + " --quiet --out " + out.string()).status, 0);
  for (const auto& entry : std::filesystem::directory_iterator(out))
    EXPECT_EQ(entry.path().filename().string().find("distribution"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace contactbench
