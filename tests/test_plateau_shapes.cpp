// Why the multi-plateaus model overestimates the contact area (docs/theory.md section 8), checked on the
// program itself: on a sampled paraboloid its area at a given load is 2^(2/3) x Hertz's, on a sampled cone
// pi/2 x Sneddon's; the project's Hertz-consistent variant (theories/plateau_hertz.hpp) gives Hertz's area on
// the paraboloid and pi/(2 sqrt 2) x Sneddon's on the cone.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "contactbench/core/sweep.hpp"
#include "contactbench/theories/plateau_hertz.hpp"
#include "contactbench/theories/plateau_model.hpp"

namespace contactbench {
namespace {

constexpr Index kN = 512, kCentre = 256;  // lattice, apex on the node (256, 256)
constexpr Real kDx = 1e-6;                // [m]

// An axisymmetric body h(r) <= 0 with its apex at 0, sampled on the lattice (non-periodic).
Surface sampled(const std::function<Real(Real)>& height_at_radius) {
  HeightMap h(kN, kN);
  for (Index iy = 0; iy < kN; ++iy)
    for (Index ix = 0; ix < kN; ++ix)
      h(iy, ix) = height_at_radius(
          std::hypot(static_cast<Real>(ix - kCentre), static_cast<Real>(iy - kCentre)) * kDx);
  const Real l = static_cast<Real>(kN) * kDx;
  return Surface(Grid{.nx = kN, .ny = kN, .lx = l, .ly = l, .periodic = false}, h);
}

// The exact contact area fraction at the load P/(E* A0) = p, and the radius [px] of the bearing disc that the
// paper's model cuts at that load (what bounds the lattice's error).
struct Shape {
  std::function<Real(Real)> height_at_radius;
  std::function<Real(Real)> exact_area;    // A/A0 at load p
  std::function<Real(Real)> model_radius;  // bearing radius [px] of the paper's model at load p
};

// Loads at which the paper's model cuts a bearing disc of 60 ... 200 px radius.
std::vector<Real> loads_for_radii(const Shape& shape, const LoadAreaCurve& model) {
  std::vector<Real> loads;
  for (const Real rho : {60.0, 80.0, 100.0, 130.0, 160.0, 200.0}) {
    // model_radius is increasing in p: bisect between the model's smallest and largest loads.
    Real lo = model.load[1], hi = model.load.back();
    for (int k = 0; k < 200; ++k) {
      const Real mid = std::sqrt(lo * hi);
      (shape.model_radius(mid) < rho ? lo : hi) = mid;
    }
    loads.push_back(hi);
  }
  return loads;
}

// Tolerance, from the lattice (as tests/test_plateau_model.cpp derives for the load): the count of lattice
// points in a disc of radius rho [px] is within pi ((rho + c)^2 - rho^2) of pi rho^2, c = sqrt(2)/2, so the
// area is within 2c/rho + (c/rho)^2 relative; the load (an integral of sqrt(A_c)) within 1.5c/rho for a
// paraboloid and 2c/rho for a cone, which moves the area at equal load by (2/3) 1.5c/rho (A ~ P^(2/3)) and by
// 2c/rho (A ~ P) respectively. Sum: 2.12/rho (paraboloid), 2.83/rho (cone); the tests allow 2.2/rho and
// 3/rho: 3.7 % and 5 % at 60 px, far below the factors 1.59 and 1.57 that are being checked. Measured on this
// lattice (both shapes, both topologies, the paper's model and the variant): at most 2.9e-3.
void expect_ratio(const Shape& shape, Real lattice_factor, Real paper_ratio, Real variant_ratio) {
  const Surface surface = sampled(shape.height_at_radius);
  for (const Topology topology :
       {Topology{Connectivity::four, false, false}, Topology{Connectivity::eight, false, false}}) {
    const SweepCurve cut = sweep(surface, SweepLevels::exact(), topology, 2);
    const LoadAreaCurve model = plateau_model(cut);
    const std::vector<Real> loads = loads_for_radii(shape, model);
    const LoadAreaCurve paper = plateau_curve_at_loads(cut, model, loads);
    const LoadAreaCurve variant = plateau_hertz_curve_at_loads(cut, model, loads);
    for (std::size_t k = 0; k < loads.size(); ++k) {
      const Real exact = shape.exact_area(loads[k]);
      const Real tolerance = lattice_factor / shape.model_radius(loads[k]);
      EXPECT_NEAR(paper.area_fraction[k] / exact / paper_ratio, 1, tolerance)
          << "paper's model, load " << loads[k] << ", " << describe(topology);
      // The variant at load p is the model at sqrt(2) p, whose disc is larger: the paper's tolerance holds.
      EXPECT_NEAR(variant.area_fraction[k] / exact / variant_ratio, 1, tolerance)
          << "variant, load " << loads[k] << ", " << describe(topology);
      EXPECT_EQ(variant.spots[k], 1);
    }
  }
}

TEST(PlateauShapes, ParaboloidAreaIsTwoToTheTwoThirdsHertzAndTheVariantIsHertz) {
  // h = -r^2/(2R), R = 1 mm. Hertz: a^3 = 3 P R / (4 E*), A = pi a^2. The paper's model cuts a disc of radius
  // sqrt(2 R delta) at approach delta and carries P = sqrt(2) (4/3) E* R^(1/2) delta^(3/2).
  const Real big_r = 1e-3, a0 = static_cast<Real>(kN * kN) * kDx * kDx;
  const Shape paraboloid{
      .height_at_radius = [=](Real r) { return -r * r / (2 * big_r); },
      .exact_area = [=](Real p) { return pi * std::pow(3 * p * a0 * big_r / 4, 2.0 / 3.0) / a0; },
      .model_radius =
          [=](Real p) {
            const Real delta = std::pow(3 * p * a0 / (4 * std::numbers::sqrt2 * std::sqrt(big_r)), 2.0 / 3.0);
            return std::sqrt(2 * big_r * delta) / kDx;
          },
  };
  expect_ratio(paraboloid, 2.2, std::pow(2.0, 2.0 / 3.0), 1.0);
}

TEST(PlateauShapes, ConeAreaIsHalfPiSneddonAndTheVariantPiOverTwoRootTwo) {
  // h = -r tan(beta), tan(beta) = 0.05. Sneddon's cone: P = (pi/2) E* a^2 tan(beta), so A/A0 = 2 p /
  // tan(beta). The paper's model cuts a disc of radius delta/tan(beta) and carries P = E* delta^2 /
  // tan(beta).
  const Real slope = 0.05, a0 = static_cast<Real>(kN * kN) * kDx * kDx;
  const Shape cone{
      .height_at_radius = [=](Real r) { return -r * slope; },
      .exact_area = [=](Real p) { return 2 * p / slope; },
      .model_radius = [=](Real p) { return std::sqrt(p * a0 * slope) / slope / kDx; },
  };
  expect_ratio(cone, 3.0, pi / 2, pi / (2 * std::numbers::sqrt2));
}

TEST(PlateauShapes, VariantIsTheModelScaled) {
  // P_H = P/sqrt(2), A_H = A_c/2 at every level (docs/theory.md section 8.3), to round-off.
  const Surface surface = sampled([](Real r) { return -r * r / 2e-3; });
  const SweepCurve cut = sweep(surface, SweepLevels::paper(50), {Connectivity::four, false, false}, 1);
  const LoadAreaCurve model = plateau_model(cut);
  const LoadAreaCurve variant = plateau_hertz(model);
  ASSERT_EQ(variant.load.size(), model.load.size());
  EXPECT_EQ(variant.method, "plateau_hertz");
  EXPECT_NE(variant.parameters.find("not the paper's model"), std::string::npos);
  for (std::size_t j = 0; j < model.load.size(); ++j) {
    EXPECT_DOUBLE_EQ(variant.load[j], model.load[j] / std::numbers::sqrt2);
    EXPECT_DOUBLE_EQ(variant.area_fraction[j], model.area_fraction[j] / 2);
    EXPECT_EQ(variant.separation[j], model.separation[j]);
  }
}

TEST(PlateauShapes, VariantGivesNoAnswerWhereTheCutReachesTheBottom) {
  const Surface surface = sampled([](Real r) { return -r * r / 2e-3; });
  const SweepCurve cut = sweep(surface, SweepLevels::exact(), {Connectivity::four, false, false}, 1);
  const LoadAreaCurve model = plateau_model(cut);
  const std::vector<Real> loads = {model.load.back() / 4, model.load.back()};  // the second is beyond sqrt(2)
  const LoadAreaCurve variant = plateau_hertz_curve_at_loads(cut, model, loads);
  EXPECT_TRUE(std::isfinite(variant.area_fraction[0]));
  EXPECT_TRUE(std::isnan(variant.area_fraction[1]));
  EXPECT_NE(variant.parameters.find("no answer"), std::string::npos);
}

}  // namespace
}  // namespace contactbench
