// The multi-plateaus model (theories/plateau_model.hpp, docs/theory.md section 4): the sum it promises,
// Sneddon's flat punch exactly, sqrt(2) x Hertz on a lattice paraboloid, monotonicity and the paper's levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/sweep.hpp"
#include "contactbench/theories/plateau_model.hpp"
#include "random_surface.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

using testing::um;

using testing::random_surface;

// docs/theory.md section 4 (the paper's eq. 3) as the header spells it out: P/(E* A0) summed over levels with
// the value of sqrt(A_c N) reported at the lower level of each step (right endpoint), A_c = area_fraction A0.
std::vector<Real> expected_load(const SweepCurve& c) {
  std::vector<Real> load(c.z.size(), 0.0);
  for (std::size_t j = 1; j < c.z.size(); ++j) {
    const Real ac = c.area_fraction[j] * c.nominal_area;
    load[j] = load[j - 1] + 2 / std::sqrt(pi) * (c.z[j - 1] - c.z[j]) *
                                std::sqrt(ac * static_cast<Real>(c.spots[j])) / c.nominal_area;
  }
  return load;
}

// The exact curve's load at any z: between two exact levels A_c N is constant, so P is linear in z there.
Real load_at(const LoadAreaCurve& exact, Real z) {
  const std::vector<Real>& s = exact.separation;  // descending
  if (z >= s.front()) return 0;
  for (std::size_t j = 1; j < s.size(); ++j)
    if (z >= s[j])
      return exact.load[j] + (exact.load[j - 1] - exact.load[j]) * (z - s[j]) / (s[j - 1] - s[j]);
  ADD_FAILURE() << "z = " << z << " below the lowest exact level";
  return exact.load.back();
}

void expect_rows_follow_the_sweep(const SweepCurve& sweep, const LoadAreaCurve& curve) {
  const std::size_t n = sweep.z.size();
  ASSERT_EQ(curve.load.size(), n);
  ASSERT_EQ(curve.area_fraction.size(), n);
  ASSERT_EQ(curve.separation.size(), n);
  ASSERT_EQ(curve.spots.size(), n);
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_EQ(curve.separation[j], sweep.z[j]) << "row " << j;
    EXPECT_EQ(curve.area_fraction[j], sweep.area_fraction[j]) << "row " << j;
    EXPECT_EQ(curve.spots[j], static_cast<Real>(sweep.spots[j])) << "row " << j;
  }
}

TEST(PlateauModel, LoadIsTheRightEndpointSumOfTheSweep) {
  const Surface s = random_surface(48, 11);
  for (const Topology t :
       {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, false, false}})
    for (const SweepLevels levels :
         {SweepLevels::exact(), SweepLevels::uniform(64), SweepLevels::paper(500)}) {
      const SweepCurve c = sweep(s, levels, t, 2);
      const LoadAreaCurve curve = plateau_model(c);
      expect_rows_follow_the_sweep(c, curve);
      const std::vector<Real> want = expected_load(c);
      // Same terms, possibly summed in another order: round-off of a few thousand additions.
      for (std::size_t j = 0; j < want.size(); ++j)
        ASSERT_NEAR(curve.load[j], want[j], 1e-12 * want.back()) << describe(t) << ", row " << j;
    }
}

TEST(PlateauModel, ParametersSayWhichTopologyWasUsed) {
  // docs/theory.md section 3: every output says which connectivity and wrap were used.
  const Surface s = random_surface(16, 3);
  for (const Topology t :
       {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, true, false},
        Topology{Connectivity::eight, false, false}}) {
    const LoadAreaCurve curve = plateau_model(sweep(s, SweepLevels::exact(), t));
    EXPECT_FALSE(curve.method.empty());
    EXPECT_NE(curve.parameters.find(describe(t)), std::string::npos)
        << "parameters \"" << curve.parameters << "\" do not say \"" << describe(t) << "\"";
  }
}

// A flat-ended cylinder: 1 um on the lattice points within `radius` px of the centre of a 64 x 64 grid
// (1 um spacing), 0 elsewhere.
struct FlatPunch {
  Surface surface;
  Real contact_area;  // A_c: the disc's pixel area [m^2]
};

FlatPunch flat_punch(Real radius) {
  const Index n = 64;
  HeightMap h(n, n);
  Index inside = 0;
  for (Index iy = 0; iy < n; ++iy)
    for (Index ix = 0; ix < n; ++ix) {
      const Real r2 = static_cast<Real>((ix - 32) * (ix - 32) + (iy - 32) * (iy - 32));
      const bool in = r2 <= radius * radius;
      h(iy, ix) = in ? 1 * um : 0.0;
      inside += in ? 1 : 0;
    }
  const Grid grid{
      .nx = n, .ny = n, .lx = static_cast<Real>(n) * um, .ly = static_cast<Real>(n) * um, .periodic = false};
  return {Surface(grid, h), static_cast<Real>(inside) * um * um};
}

TEST(PlateauModel, FlatPunchIsSneddonExactly) {
  // One spot of area A_c for every depth: the model's cylinder has radius a = sqrt(A_c / pi) and Sneddon
  // gives P = 2 E* a delta exactly, so P/(E* A0) = 2 sqrt(A_c/pi) delta / A0. Only round-off separates the
  // sum from that (a handful of operations on numbers of size 1): 1e-12 relative.
  for (const Real radius : {3.0, 10.0, 20.5})
    for (const Topology t :
         {Topology{Connectivity::four, false, false}, Topology{Connectivity::eight, true, true}}) {
      const FlatPunch punch = flat_punch(radius);
      const Real a0 = punch.surface.grid().nominal_area();
      const Real a = std::sqrt(punch.contact_area / pi);
      // Exact levels: the top (nothing above) and 0 (the disc above), delta = 1 um.
      const SweepCurve exact = sweep(punch.surface, SweepLevels::exact(), t);
      const LoadAreaCurve e = plateau_model(exact);
      ASSERT_EQ(e.load.size(), 2u);
      expect_rows_follow_the_sweep(exact, e);
      EXPECT_EQ(e.load[0], 0.0);
      EXPECT_NEAR(e.load[1], 2 * a * (1 * um) / a0, 1e-12 * e.load[1]) << "radius " << radius;
      EXPECT_EQ(e.separation[1], 0.0);
      EXPECT_DOUBLE_EQ(e.area_fraction[1], punch.contact_area / a0);
      EXPECT_EQ(e.spots[1], 1.0);

      // Uniform levels from 1 um to 0: at the interior levels delta = z[0] - z[j] lies in (0, 1 um) and the
      // set above is the disc, so the load grows linearly with delta. (The last level, 0 to round-off, is
      // left out: a round-off below 0 would put the whole grid above it.)
      const SweepCurve uniform = sweep(punch.surface, SweepLevels::uniform(10), t);
      const LoadAreaCurve u = plateau_model(uniform);
      expect_rows_follow_the_sweep(uniform, u);
      EXPECT_EQ(u.load[0], 0.0);
      for (std::size_t j = 1; j + 1 < u.load.size(); ++j) {
        const Real delta = uniform.z[0] - uniform.z[j];
        ASSERT_GT(delta, 0);
        ASSERT_LT(delta, 1 * um);
        EXPECT_NEAR(u.load[j], 2 * a * delta / a0, 1e-12 * u.load[j]) << "radius " << radius << ", row " << j;
        EXPECT_DOUBLE_EQ(u.area_fraction[j], punch.contact_area / a0);
        EXPECT_EQ(u.separation[j], uniform.z[j]);
      }
    }
  // The paper's levels on the punch with its mean removed (the paper's levels end at the mean plane 0,
  // which now lies between the disc and the rest): every level below the top sees the disc.
  const FlatPunch punch = flat_punch(10.0);
  const Surface centred = punch.surface.centred();
  const Real a0 = centred.grid().nominal_area();
  const Real a = std::sqrt(punch.contact_area / pi);
  const SweepCurve paper = sweep(centred, SweepLevels::paper(50), {Connectivity::four, false, false});
  const LoadAreaCurve p = plateau_model(paper);
  expect_rows_follow_the_sweep(paper, p);
  for (std::size_t j = 1; j < p.load.size(); ++j) {
    const Real delta = paper.z[0] - paper.z[j];
    EXPECT_NEAR(p.load[j], 2 * a * delta / a0, 1e-12 * p.load[j]) << "row " << j;
  }
}

TEST(PlateauModel, ParaboloidIsSqrt2TimesHertz) {
  // h = -r^2 / (2R) sampled on a 512 x 512 lattice, 1 um spacing, apex on the node (256, 256), R = 1 mm.
  // Continuum: A_c = 2 pi R delta and N = 1 (a lattice disc is 4-connected), so eq. 3 gives
  // P = sqrt(2) (4/3) E* R^(1/2) delta^(3/2), sqrt(2) times Hertz.
  //
  // Tolerance, from the lattice. At depth s the set above is the lattice points in the open disc of radius
  // rho(s) = sqrt(2 R s) / dx [px]. Their count n satisfies pi (rho - c)^2 <= n <= pi (rho + c)^2 with
  // c = sqrt(2)/2 (each point's unit cell lies within rho + c; every point of the disc of radius rho - c lies
  // in the cell of a point inside), so |sqrt(A_c) - sqrt(pi) rho dx| <= sqrt(pi) c dx at every s. Integrated
  // over s in [0, delta] that bounds |P_lattice - P_continuum| by 2 c dx delta / A0, while P_continuum =
  // (4/3) dx delta rho / A0: a relative error of at most 1.5 c / rho = 1.06 / rho at contact radius rho.
  // Exact levels sum the lattice's step function exactly, so that bound (plus round-off) is the
  // tolerance: 3.5 % at rho = 30 px, 1.06 % at 100 px, 0.53 % at 200 px.
  // Measured (this lattice, radii 30..240 px, both topologies): worst relative error 3.5e-5 (Gauss's circle
  // problem: the count's error is far below the boundary length on average, and the integral averages it).
  const Index n = 512, centre = 256;
  const Real dx = 1 * um, big_r = 1e-3;
  HeightMap h(n, n);
  for (Index iy = 0; iy < n; ++iy)
    for (Index ix = 0; ix < n; ++ix) {
      const Real r2 =
          static_cast<Real>((ix - centre) * (ix - centre) + (iy - centre) * (iy - centre)) * dx * dx;
      h(iy, ix) = -r2 / (2 * big_r);
    }
  const Grid grid{
      .nx = n, .ny = n, .lx = static_cast<Real>(n) * dx, .ly = static_cast<Real>(n) * dx, .periodic = false};
  const Surface s(grid, h);
  const Real a0 = grid.nominal_area();
  for (const Topology t :
       {Topology{Connectivity::four, false, false}, Topology{Connectivity::eight, true, true}}) {
    const SweepCurve c = sweep(s, SweepLevels::exact(), t, 2);
    const LoadAreaCurve curve = plateau_model(c);
    ASSERT_EQ(curve.load.size(), c.z.size());
    Real worst = 0;
    std::size_t next = 0;
    const std::vector<Real> radii = {30, 45, 60, 80, 100, 130, 160, 200, 240};  // contact radius [px]
    for (std::size_t j = 1; j < c.z.size() && next < radii.size(); ++j) {
      const Real delta = c.z[0] - c.z[j];
      const Real rho = std::sqrt(2 * big_r * delta) / dx;
      if (rho < radii[next]) continue;
      ++next;
      ASSERT_EQ(c.spots[j], 1) << "rho = " << rho;
      const Real hertz = 4.0 / 3.0 * std::sqrt(big_r) * std::pow(delta, 1.5) / a0;
      const Real error = curve.load[j] / (std::sqrt(2.0) * hertz) - 1;
      EXPECT_LT(std::abs(error), 1.5 * (std::sqrt(2.0) / 2) / rho)
          << "rho = " << rho << " px, " << describe(t);
      worst = std::max(worst, std::abs(error));
    }
    EXPECT_EQ(next, radii.size());
    // The measured error, held to a fraction of the bound: a coarse wrong factor (say a level too few or an
    // area off by one shell) would not survive this, while the lattice bound above is what is guaranteed.
    EXPECT_LT(worst, 1e-3) << describe(t);
    RecordProperty("worst_relative_error_" + std::to_string(static_cast<int>(t.connectivity)),
                   std::to_string(worst));
  }
}

TEST(PlateauModel, LoadAndAreaAreMonotone) {
  for (const std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
    const Surface s = random_surface(40, seed);
    for (const Topology t :
         {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, false, false},
          Topology{Connectivity::four, true, false}})
      for (const SweepLevels levels :
           {SweepLevels::exact(), SweepLevels::uniform(30), SweepLevels::paper(500)}) {
        const LoadAreaCurve curve = plateau_model(sweep(s, levels, t, 2));
        ASSERT_FALSE(curve.load.empty());
        EXPECT_EQ(curve.load.front(), 0.0) << describe(t);
        EXPECT_EQ(curve.area_fraction.front(), 0.0) << describe(t);
        for (std::size_t j = 1; j < curve.load.size(); ++j) {
          ASSERT_GE(curve.load[j], curve.load[j - 1]) << describe(t) << ", row " << j;
          ASSERT_GE(curve.area_fraction[j], curve.area_fraction[j - 1]) << describe(t) << ", row " << j;
        }
        EXPECT_GT(curve.load.back(), 0.0);
      }
  }
}

TEST(PlateauModel, PaperLevelsApproachTheExactSum) {
  // The paper's levels give a right-endpoint Riemann sum of the piecewise-constant sqrt(A_c N); its error
  // shrinks with the step, so 5000 levels must lie closer to the exact sum than 500 levels. The exact curve
  // is linear in z between its levels, so it can be evaluated at the paper's levels by interpolation.
  for (const std::uint64_t seed : {4ULL, 5ULL}) {
    const Surface s = random_surface(64, seed);
    for (const Topology t :
         {Topology{Connectivity::four, true, true}, Topology{Connectivity::eight, true, true}}) {
      const LoadAreaCurve exact = plateau_model(sweep(s, SweepLevels::exact(), t, 2));
      Real error[2] = {0, 0};
      const Index counts[2] = {500, 5000};
      for (int k = 0; k < 2; ++k) {
        const LoadAreaCurve paper = plateau_model(sweep(s, SweepLevels::paper(counts[k]), t, 2));
        for (std::size_t j = 0; j < paper.load.size(); ++j)
          error[k] = std::max(error[k], std::abs(paper.load[j] - load_at(exact, paper.separation[j])));
      }
      const Real scale = load_at(exact, 0.0);
      // Measured (seeds 4, 5; 4- and 8-connectivity): worst error / load at z = 0 is 0.27-0.30 % with 500
      // levels and 0.026-0.039 % with 5000, about the factor 10 of a first-order sum. The bounds leave 3x.
      EXPECT_LT(error[1], 0.5 * error[0]) << describe(t);
      EXPECT_LT(error[0], 0.01 * scale) << describe(t);
      EXPECT_LT(error[1], 0.0015 * scale) << describe(t);
      RecordProperty("relative_error_500_vs_5000_seed" + std::to_string(seed) + "_" +
                         std::to_string(static_cast<int>(t.connectivity)),
                     std::to_string(error[0] / scale) + " " + std::to_string(error[1] / scale));
    }
  }
}

// Sampling at requested loads is exact: at a level's own load the answer is that level's row, and a load
// between two levels has the lower level's area and the separation where the linear P(z) reaches it, which
// load_at inverts to round-off (1e-12 relative: one division and one product).
TEST(PlateauModel, CurveAtLoadsIsExactBetweenLevels) {
  const Surface surface = random_surface(32, 5);
  const SweepCurve exact =
      sweep(surface, SweepLevels::exact(), Topology::for_surface(Connectivity::four, true));
  const LoadAreaCurve model = plateau_model(exact);
  const std::size_t j = model.load.size() / 2;
  const Real between = 0.5 * (model.load[j - 1] + model.load[j]);
  const Real beyond = model.load.back() + 1e-3;
  const std::vector<Real> loads{between, model.load[j], beyond};
  const LoadAreaCurve at = plateau_curve_at_loads(exact, model, loads);
  ASSERT_EQ(at.load.size(), 3u);
  EXPECT_EQ(at.area_fraction[0], model.area_fraction[j]);
  EXPECT_EQ(at.spots[0], model.spots[j]);
  EXPECT_NEAR(load_at(model, at.separation[0]), between, 1e-12 * between);
  EXPECT_EQ(at.area_fraction[1], model.area_fraction[j]);
  EXPECT_NEAR(at.separation[1], model.separation[j], 1e-12 * std::abs(model.separation[j]));
  // Below the lowest height: full contact, one spot, and the approach of a flat punch of area A0 (Sneddon).
  EXPECT_EQ(at.area_fraction[2], 1);
  EXPECT_EQ(at.spots[2], 1);
  const Real approach = model.separation.back() - at.separation[2];
  EXPECT_NEAR(1e-3, 2 / std::sqrt(pi) * std::sqrt(1 / exact.nominal_area) * approach, 1e-15);
  EXPECT_NE(at.parameters.find("full contact"), std::string::npos) << at.parameters;
  // The paper's levels stop at the mean plane: beyond them there is no answer, and the parameters say so.
  const SweepCurve paper =
      sweep(surface, SweepLevels::paper(), Topology::for_surface(Connectivity::four, true));
  const LoadAreaCurve paper_model = plateau_model(paper);
  const LoadAreaCurve paper_at =
      plateau_curve_at_loads(paper, paper_model, std::vector<Real>{2 * paper_model.load.back()});
  EXPECT_TRUE(std::isnan(paper_at.area_fraction[0]));
  EXPECT_NE(paper_at.parameters.find("no answer"), std::string::npos) << paper_at.parameters;
  EXPECT_THROW(plateau_curve_at_loads(exact, model, std::vector<Real>{-1.0}), Error);
}

}  // namespace
}  // namespace contactbench
