// The cheap models' mean gap and stiffness (docs/theory.md section 12): each analytic -dP/dd against finite
// differences of the model's own load, Persson's pressure distribution against its limits, and the scene
// key `compare`: a scene without it runs what it ran before, one with it gives every quantity or "n/a".
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>

#include "contactbench/app/comparison.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/report_writers.hpp"
#include "contactbench/app/scene_run.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/theories/bush_gibson_thomas.hpp"
#include "contactbench/theories/greenwood_williamson.hpp"
#include "contactbench/theories/isotropic_moments.hpp"
#include "contactbench/theories/persson.hpp"
#include "contactbench/theories/persson_gap.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

Surface surface_a(Index n) {
  const Grid grid{.nx = n, .ny = n, .lx = 100e-6, .ly = 100e-6, .periodic = true};
  return generate_surface(grid, paper::surface_a(), 7);
}

// A central difference of step 1e-4 relative in the separation: its truncation error is of order 1e-8 of
// the slope for these smooth functions, round-off about 1e-16/1e-4 = 1e-12; 1e-6 bounds both.
constexpr Real kDifferenceTolerance = 1e-6;

TEST(GapTheories, GreenwoodWilliamsonStiffnessIsMinusDLoadDSeparation) {
  const GwParameters gw = mccool_parameters(spectral_moments(surface_a(128)));
  for (const Real t : {-1.0, 0.5, 2.0, 4.0}) {
    const Real h = 1e-4 * gw.sigma_s;
    const Real difference = -(gw_load(gw, t + h / gw.sigma_s) - gw_load(gw, t - h / gw.sigma_s)) / (2 * h);
    EXPECT_NEAR(gw_stiffness(gw, t) / difference, 1, kDifferenceTolerance) << "t = " << t;
  }
}

TEST(GapTheories, BushGibsonThomasStiffnessIsMinusDLoadDSeparation) {
  const SpectralMoments moments = spectral_moments(surface_a(128));
  const BushGibsonThomas model(isotropic_moments(moments, "bgt"));
  const Real rms = std::sqrt(moments.m0);
  for (const Real zeta : {0.0, 1.0, 2.5}) {
    const Real d = zeta * rms, h = 1e-4 * rms;
    const Real difference = -(model.load(d + h) - model.load(d - h)) / (2 * h);
    EXPECT_NEAR(model.stiffness(d) / difference, 1, kDifferenceTolerance) << "d/h_rms = " << zeta;
  }
}

TEST(GapTheories, PerssonStiffnessIsMinusDLoadDMeanGap) {
  // The mean gap from the tabulated inner integral (linear interpolation in ln s, step 7.4e-4: about 1e-7
  // relative), the stiffness from the closed-form derivative: a central difference in the load of step 1 %
  // (truncation about 1e-4 of the slope) agrees to 1e-3.
  const PerssonGap persson(fourier_coefficients(surface_a(128)));
  Real previous = std::numeric_limits<Real>::infinity();
  for (const Real load : {1e-4, 1e-3, 1e-2, 5e-2}) {
    const Real u = persson.mean_gap(load);
    EXPECT_GT(u, 0);
    EXPECT_LT(u, previous);  // the gap closes as the load grows
    previous = u;
    const Real step = 0.01 * load;
    const Real difference =
        -2 * step / (persson.mean_gap(load + step) - persson.mean_gap(load - step));  // d load / d u
    EXPECT_NEAR(persson.stiffness(load) / difference, 1, 1e-3) << "load " << load;
  }
}

// Persson's mean gap is a function of the lattice spectrum as a set of (|q|, C) pairs: neither the order of
// modes of equal |q| nor modes of round-off size may move it. Before w(q) was shared by a shell, the lowest
// shell's modes (kx = 1, ky = 0: two modes; kx = 0, ky = +-1: one each) took w by their order, so transposing
// the surface, or giving its empty modes round-off (~1e-57 of C: the slabs' surface gathered under mpiexec,
// docs/mpi.md), moved the mean gap by 1 to 8 %. What is left is the order of additions inside a shell, a few
// ulp; 1e-13.
TEST(GapTheories, PerssonMeanGapDependsOnTheSpectrumNotOnTheOrderOfEqualModes) {
  const Surface surface = surface_a(64);
  const FourierCoefficients c = fourier_coefficients(surface);
  const HeightMap transposed_heights = surface.heights().transpose();
  const FourierCoefficients transposed = fourier_coefficients(Surface(surface.grid(), transposed_heights));
  // The empty modes (C exactly 0 here) given round-off amplitudes, 1e-25 of the rms height's.
  FourierCoefficients noisy = c;
  Index filled = 0;
  for (Index row = 0; row < noisy.hhat.rows(); ++row)
    for (Index col = 0; col < noisy.hhat.cols(); ++col)
      if ((row != 0 || col != 0) && noisy.hhat(row, col) == Complex(0, 0)) {
        noisy.hhat(row, col) = Complex(1e-25 * surface.rms_height() * static_cast<Real>(row + col), 0);
        ++filled;
      }
  ASSERT_GT(filled, 0);
  for (const Real load : {1e-3, 1e-2}) {
    const Real gap = PerssonGap(c).mean_gap(load);
    EXPECT_NEAR(PerssonGap(transposed).mean_gap(load) / gap, 1, 1e-13) << "transposed, load " << load;
    EXPECT_NEAR(PerssonGap(noisy).mean_gap(load) / gap, 1, 1e-13) << "round-off modes, load " << load;
  }
}

TEST(GapTheories, PerssonPressureDistributionInFullContactIsTheGaussian) {
  // Far into full contact (load / (2 sqrt g) = 6: the image term is exp(-36) smaller) P(sigma) is the
  // Gaussian of mean p and variance 2 G = (E*^2/4) gbar^2, the variance of p0 + (E*/2)|q| h(q) over a
  // surface in full contact; its integral is the area fraction erf(load/(2 sqrt g)) and its first moment the
  // load. Midpoint sums over 20000 steps h on [0, load + 12 sqrt(2 g)]: their error is at most
  // (length) h^2 max|f''|/24, about 2.2 x 1.2e-8 x 70/24 = 8e-8 here (f'' ~ f/variance); 1e-7 bounds it.
  const Real q3 = 0.02, g = pi / 4 * q3, variance = 2 * g;
  const Real load = 12 * std::sqrt(g);
  for (const Real s : {load - 2 * std::sqrt(variance), load, load + 0.5 * std::sqrt(variance)}) {
    const Real gaussian = std::exp(-(s - load) * (s - load) / (2 * variance)) / std::sqrt(2 * pi * variance);
    EXPECT_NEAR(persson_pressure_density(s, load, q3) / gaussian, 1, 1e-12);
  }
  for (const Real partial : {0.3, 1.0, 12.0}) {  // load / (2 sqrt g): partial to full contact
    const Real p = partial * 2 * std::sqrt(g);
    const Real top = p + 12 * std::sqrt(variance), step = top / 20000;
    Real zeroth = 0, first = 0;
    for (int i = 0; i < 20000; ++i) {
      const Real s = (i + 0.5) * step, density = persson_pressure_density(s, p, q3);
      zeroth += density * step;
      first += s * density * step;
    }
    EXPECT_NEAR(zeroth, persson_area_fraction_psd(p, q3), 1e-7) << partial;
    EXPECT_NEAR(first / p, 1, 1e-7) << partial;
  }
}

const std::string kScene = kSmallSurfaceAndMaterial + R"([loads]
values = [1e-3, 1e-2]
[methods.bem]
[methods.plateau]
[methods.gw_mccool]
[methods.bgt_linear]
[methods.persson]
)";

std::string curves_header(const SceneReport& report) {
  std::ostringstream csv;
  write_curves_csv(csv, report, current_provenance(1, "test"));
  std::string line, last;
  std::istringstream lines(csv.str());
  while (std::getline(lines, line))
    if (line.rfind("method,", 0) == 0) last = line;
  return last;
}

TEST(CompareKey, AreaAloneRunsWhatItRanBefore) {
  const SceneReport report =
      run_scene(parse_scene("name = \"areas\"\n" + kScene, "test.toml"), {.threads = 1, .observer = nullptr});
  for (const StageRecord& stage : report.stages)
    EXPECT_EQ(stage.name.find("stiffness"), std::string::npos) << stage.name;
  EXPECT_EQ(curves_header(report).find("mean_gap,stiffness"), std::string::npos);
  for (const MethodResult& m : report.methods) {
    EXPECT_TRUE(m.curve.mean_gap.empty()) << m.label;
    EXPECT_TRUE(m.curve.stiffness.empty()) << m.label;
  }
  EXPECT_TRUE(compare(report).methods.front().quantities.empty());
}

TEST(CompareKey, EveryQuantityOrNotApplicable) {
  const Scene scene =
      parse_scene("name = \"all\"\ncompare = [\"stiffness\", \"mean_gap\"]\n" + kScene, "test.toml");
  ASSERT_EQ(scene.compare.size(), 3u);  // the area first, then in the one order
  const SceneReport report = run_scene(scene, {.threads = 1, .observer = nullptr});
  EXPECT_NE(curves_header(report).find("spots,mean_gap,stiffness"), std::string::npos);
  const Comparison comparison = compare(report);
  for (std::size_t m = 0; m < report.methods.size(); ++m) {
    const MethodResult& r = report.methods[m];
    const bool gives = r.method != "bgt_linear";  // a proportionality law: no separation, no gap
    ASSERT_EQ(comparison.methods[m].quantities.size(), 2u);
    for (const QuantityComparison& q : comparison.methods[m].quantities) {
      EXPECT_EQ(q.given, gives) << r.label;
      if (!gives) continue;
      // Finite; a stiffness > 0. (A summit model's mean gap is its separation from the mean plane, which
      // goes below 0 at large loads: reported as it is, docs/theory.md 12.4.)
      for (const Real v : r.curve.values(q.quantity)) {
        EXPECT_TRUE(std::isfinite(v)) << r.label << " " << quantity_name(q.quantity);
        if (q.quantity == Quantity::stiffness) {
          EXPECT_GT(v, 0) << r.label;
        }
      }
      if (r.label != "bem") {
        EXPECT_EQ(q.relative_error.size(), 2u) << r.label;
      }
    }
  }
  // The periodic BEM's mean gap is its separation (docs/theory.md 12.1).
  const MethodResult& bem = report.methods.front();
  for (std::size_t k = 0; k < 2; ++k)
    EXPECT_NEAR(bem.curve.mean_gap[k] / bem.curve.separation[k], 1, 1e-9);
  std::ostringstream table;
  write_table_md(table, report, comparison, current_provenance(1, "test"));
  EXPECT_NE(table.str().find("n/a (the method gives none)"), std::string::npos);
}

TEST(CompareKey, UnknownQuantityIsRefusedByName) {
  try {
    parse_scene("name = \"bad\"\ncompare = [\"area\", \"gap\"]\n" + kScene, "test.toml");
    FAIL() << "accepted an unknown quantity";
  } catch (const SceneError& e) {
    const std::string text = e.what();
    EXPECT_NE(text.find("compare[1]"), std::string::npos) << text;
    EXPECT_NE(text.find("\"mean_gap\""), std::string::npos) << text;
  }
}

}  // namespace
}  // namespace contactbench
