// A line scan drives the analytic theories (docs/formats.md "line scans"): levelling of a profile, the
// isotropic moments a profile gives, a scene over a scan file, and the refusals of every method that needs
// heights over an area.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/app/scene.hpp"
#include "contactbench/app/scene_error.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/profile_levelling.hpp"
#include "contactbench/core/profile_statistics.hpp"
#include "contactbench/theories/bgt_linear.hpp"
#include "contactbench/theories/bush_gibson_thomas.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/persson.hpp"
#include "test_folder.hpp"

namespace contactbench {
namespace {

// Uneven positions over [0, 1e-4] m.
std::vector<Real> uneven_x(int n) {
  std::vector<Real> x;
  for (int k = 0; k < n; ++k)
    x.push_back(1e-4 * std::pow(static_cast<Real>(k) / (n - 1), 1.7));
  return x;
}

TEST(LevelProfile, RemovesItsPolynomialExactlyOnUnevenSampling) {
  const std::vector<Real> x = uneven_x(50);
  std::vector<Real> line, parabola;
  for (const Real v : x) {
    line.push_back(2e-6 + 0.03 * v);
    parabola.push_back(2e-6 + 0.03 * v - 400 * v * v);
  }
  // A least-squares fit reproduces a polynomial of its own degree to round-off: heights of 2e-6 to 5e-6 m,
  // so 1e-18 m is a few hundred units of the last place.
  for (const Real r : level_profile(x, line, Levelling::plane))
    EXPECT_NEAR(r, 0, 1e-18);
  for (const Real r : level_profile(x, parabola, Levelling::quadratic))
    EXPECT_NEAR(r, 0, 1e-18);
  // A line is not removed by the mean, and a parabola not by the line: the residuals stay (controls).
  EXPECT_GT(std::abs(level_profile(x, line, Levelling::mean).front()), 1e-7);
  EXPECT_GT(std::abs(level_profile(x, parabola, Levelling::plane).back()), 1e-7);
  // The mean is weighted by the length each sample stands for: the trapezoidal mean of the result is zero
  // (relative to the heights' size, to round-off), although the densely sampled start is lower.
  const std::vector<Real> levelled = level_profile(x, line, Levelling::mean);
  Real integral = 0;
  for (std::size_t k = 0; k + 1 < x.size(); ++k)
    integral += 0.5 * (x[k + 1] - x[k]) * (levelled[k] + levelled[k + 1]);
  EXPECT_NEAR(integral / 1e-4, 0, 1e-3 * 1.5e-6);  // the trapezoid rule and the sample weights differ by O(h)
  EXPECT_THROW(level_profile(std::vector<Real>{0, 1, 2}, std::vector<Real>{0, 1, 3}, Levelling::quadratic),
               Error);
}

TEST(IsotropicMoments, AreTheProfilesInBothDirectionsAndHaveNoM4WhenUneven) {
  const std::vector<Real> x = uneven_x(40);
  std::vector<Real> h;
  for (const Real v : x)
    h.push_back(1e-6 * std::sin(2e5 * v));
  const SpectralMoments uneven = isotropic_moments(profile_statistics(x, h));
  EXPECT_EQ(uneven.m2x, uneven.m2y);
  EXPECT_TRUE(std::isnan(uneven.m4x) && std::isnan(uneven.m4y));
  std::vector<Real> even_x;
  for (int k = 0; k < 40; ++k)
    even_x.push_back(1e-6 * k);
  const ProfileStatistics even = profile_statistics(even_x, h);
  const SpectralMoments moments = isotropic_moments(even);
  EXPECT_EQ(moments.m0, even.m0());
  EXPECT_EQ(moments.m2x, even.m2());
  EXPECT_EQ(moments.m4x, *even.rms_curvature * *even.rms_curvature);
  EXPECT_EQ(moments.m4y, moments.m4x);
}

class LineScanScene : public testing::FolderTest {
 protected:
  LineScanScene() : FolderTest("cb_line_scan_") {
    // One row of surface A's spectrum on 512 points over 200 um (uniform sampling): the profile a stylus
    // would trace across that surface.
    const Grid grid{.nx = 512, .ny = 512, .lx = 200e-6, .ly = 200e-6, .periodic = true};
    const Surface surface =
        generate_surface(grid, {.sigma = 0.5e-6, .hurst = 0.5, .qr = 3.14e4, .qs = std::nullopt}, 3);
    for (Index k = 0; k < grid.nx; ++k) {
      x_.push_back(static_cast<Real>(k) * grid.dx());
      h_.push_back(surface.heights()(7, k));
    }
  }

  // The scan as x h text in metres, each height plus `tilt` times x.
  std::filesystem::path scan_file(const std::string& name, Real tilt = 0) const {
    std::ostringstream text;
    text.precision(17);
    for (std::size_t k = 0; k < x_.size(); ++k)
      text << x_[k] << ' ' << h_[k] + tilt * x_[k] << '\n';
    return write(name, text.str());
  }

  Scene scene(const std::filesystem::path& file, const std::string& surface_keys, const std::string& methods,
              const std::string& extra = "") const {
    return parse_scene("name = \"scan\"\n" + extra + "[surface]\nfile = \"" + file.string() + "\"\n" +
                           surface_keys +
                           "\n[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-4, 1e-3, "
                           "1e-2]\n" +
                           methods,
                       folder_ / "scan.toml");
  }

  static const std::vector<Real>& area(const SceneReport& report, const std::string& label) {
    for (const MethodResult& m : report.methods)
      if (m.label == label) return m.curve.area_fraction;
    throw Error("no method " + label);
  }

  // The refusals of a scene that must not run, as one text.
  static std::string refusal(const Scene& s) {
    try {
      run_scene(s, {.threads = 1});
    } catch (const SceneError& error) {
      return error.what();
    }
    ADD_FAILURE() << "the scene ran";
    return {};
  }

  std::vector<Real> x_, h_;
};

constexpr const char* kTheories = R"(
[methods.gw]
method = "gw_mccool"
[methods.bgt]
method = "bgt"
[methods.bgt_linear]
method = "bgt_linear"
[methods.persson]
method = "persson"
)";

TEST_F(LineScanScene, DrivesTheTheoriesWithTheProfilesIsotropicMoments) {
  const SceneReport report = run_scene(scene(scan_file("scan.txt"), "", kTheories), {.threads = 1});
  EXPECT_NE(report.line_scan.find("Isotropy assumed"), std::string::npos) << report.line_scan;
  // The scene levels nothing but removes the profile's mean, which no moment reads: the theories see the
  // moments of the profile as profile_statistics gives them, by the same arithmetic (equal to 4 ulps).
  const SpectralMoments moments = isotropic_moments(profile_statistics(x_, h_));
  const std::vector<Real> loads{1e-4, 1e-3, 1e-2};
  const Real side = x_.back() - x_.front();
  const std::vector<std::pair<std::string, LoadAreaCurve>> expected{
      {"gw", gw_mccool_curve(moments, loads, side * side)},
      {"bgt", bgt_curve(moments, loads, side * side)},
      {"bgt_linear", bgt_linear_curve(moments, loads)},
      {"persson", persson_curve(moments, loads)}};
  for (const auto& [label, curve] : expected)
    for (std::size_t i = 0; i < loads.size(); ++i)
      EXPECT_DOUBLE_EQ(area(report, label)[i], curve.area_fraction[i]) << label << " at load " << loads[i];
}

TEST_F(LineScanScene, LevellingRemovesTheScansTilt) {
  // A tilt of 0.05 (three times the profile's rms slope would not be small) enters m2 unless levelled.
  const SceneReport level = run_scene(scene(scan_file("level.txt"), "level = \"plane\"", kTheories), {});
  const SceneReport tilted =
      run_scene(scene(scan_file("tilted.txt", 0.05), "level = \"plane\"", kTheories), {.threads = 1});
  const SceneReport unlevelled = run_scene(scene(scan_file("raw.txt", 0.05), "", kTheories), {.threads = 1});
  for (const std::string label : {"gw", "bgt", "bgt_linear", "persson"})
    for (std::size_t i = 0; i < 3; ++i) {
      // The line fit removes the tilt to round-off of the fit (17 digits written, heights of 1e-6 m against a
      // tilt term of up to 1e-5 m): 1e-9 relative is far above that and far below the control's change.
      EXPECT_NEAR(area(tilted, label)[i], area(level, label)[i], 1e-9 * area(level, label)[i]) << label;
      // Control: left in, the tilt changes the area by more than 1 %.
      EXPECT_GT(std::abs(area(unlevelled, label)[i] / area(level, label)[i] - 1), 0.01) << label;
    }
}

TEST_F(LineScanScene, RefusesWhatNeedsHeightsOverAnArea) {
  const std::filesystem::path file = scan_file("scan.txt");
  const std::string text = refusal(scene(file, "", R"(
[methods.bem]
method = "bem"
[methods.plateau]
method = "plateau"
[methods.persson]
method = "persson"
)"));
  EXPECT_NE(text.find("methods.bem: the method bem needs heights over an area"), std::string::npos) << text;
  EXPECT_NE(text.find("methods.plateau: the method plateau needs heights over an area"), std::string::npos)
      << text;
  EXPECT_EQ(text.find("methods.persson"), std::string::npos) << text;
  // Persson's mean gap integrates the spectrum over the plane.
  const std::string gap = refusal(
      scene(file, "", "[methods.persson]\nmethod = \"persson\"\n", "compare = [\"area\", \"mean_gap\"]\n"));
  EXPECT_NE(gap.find("which a line scan (one profile) does not give"), std::string::npos) << gap;
  // The keys of a 2-D file do not apply, named.
  for (const std::string key : {"fill = \"mean\"", "crop = \"measured\"", "size = 1e-4", "periodic = true"}) {
    SCOPED_TRACE(key);
    try {
      run_scene(scene(file, key, kTheories), {.threads = 1});
      ADD_FAILURE() << "ran";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("surface." + key.substr(0, key.find(' '))), std::string::npos)
          << error.what();
    }
  }
}

TEST_F(LineScanScene, AnUnevenScanHasNoM4ForTheTheoriesThatReadIt) {
  std::ostringstream text;
  text.precision(17);
  const std::vector<Real> x = uneven_x(200);
  for (std::size_t k = 0; k < x.size(); ++k)
    text << x[k] << ' ' << 1e-7 * std::sin(3e5 * x[k]) + 2e-8 * std::cos(1.1e6 * x[k]) << '\n';
  const std::filesystem::path file = write("uneven.txt", text.str());
  const std::string refused = refusal(scene(file, "", kTheories));
  EXPECT_NE(refused.find("methods.gw: gw_mccool reads m4"), std::string::npos) << refused;
  EXPECT_NE(refused.find("methods.bgt: bgt reads m4"), std::string::npos) << refused;
  EXPECT_EQ(refused.find("methods.persson"), std::string::npos) << refused;
  const SceneReport report =
      run_scene(scene(file, "", "[methods.p]\nmethod = \"persson\"\n[methods.b]\nmethod = \"bgt_linear\"\n"),
                {.threads = 1});
  EXPECT_NE(report.line_scan.find("unevenly sampled (no m4)"), std::string::npos) << report.line_scan;
  EXPECT_EQ(report.methods.size(), 2u);
}

}  // namespace
}  // namespace contactbench
