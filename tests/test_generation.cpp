// The paper's generator (docs/theory.md section 2): Table 2, refinement, reproducibility, anisotropy.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <utility>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "test_constants.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

// Table 2 of the paper in the units it prints: m0 [um^2], m2 [-], m4 [um^-2].
struct Table2Row {
  Real m0, m2, m4;
};
using testing::um;

// Half a unit in the third significant digit of x: how far a value may lie from what it rounds to.
Real half_unit_of_third_digit(Real x) {
  return 0.5 * std::pow(10.0, std::floor(std::log10(x)) - 2);
}

void expect_table2(const SpectralMoments& m, Table2Row row, const char* what) {
  // The paper prints three significant digits; the issue asks for 1 %. Both profile directions must match.
  EXPECT_NEAR(m.m0 / (um * um), row.m0, tolerance::table2 * row.m0) << what;
  EXPECT_NEAR(m.m2x, row.m2, tolerance::table2 * row.m2) << what;
  EXPECT_NEAR(m.m2y, row.m2, tolerance::table2 * row.m2) << what;
  EXPECT_NEAR(m.m4x * um * um, row.m4, tolerance::table2 * row.m4) << what;
  EXPECT_NEAR(m.m4y * um * um, row.m4, tolerance::table2 * row.m4) << what;
  // Tight: each moment rounds to the printed digits, i.e. lies within half a unit of the third digit (0.45 %
  // of m2 = 0.0110, 0.11 % of m4 = 0.0446; measured -0.13 % and -0.05 % for A, -0.10 % and -0.02 % for B).
  // The exact lattice values are checked against an independent sum in LatticeMomentsEqualAnIndependentSum.
  // Rejects m2 or m4 off by 0.5 % (1 % passed).
  EXPECT_NEAR(m.m0 / (um * um), row.m0, half_unit_of_third_digit(row.m0)) << what;
  for (const Real m2 : {m.m2x, m.m2y})
    EXPECT_NEAR(m2, row.m2, half_unit_of_third_digit(row.m2)) << what;
  for (const Real m4 : {m.m4x, m.m4y})
    EXPECT_NEAR(m4 * um * um, row.m4, half_unit_of_third_digit(row.m4)) << what;
}

// The lattice moments written out independently of the generator (docs/theory.md section 2): C(q) = 1 below
// qr, (|q|/qr)^(-2(1 + H)) from qr to qs, 0 beyond qs, at k = 0 and on the Nyquist row and column; m0 =
// sigma^2 and m2x = sigma^2 sum qx^2 C / sum C, m4x likewise with qx^4, over the 256 x 256 modes q = 2 pi
// k/L.
SpectralMoments lattice_sum(const SelfAffinePsd& psd) {
  const Grid grid = paper::grid();
  const Real qs = psd.qs ? *psd.qs : std::numbers::pi / (grid.lx / static_cast<Real>(grid.nx));
  Real c_sum = 0, c_qx2 = 0, c_qy2 = 0, c_qx4 = 0, c_qy4 = 0;
  for (Index ky = -grid.ny / 2; ky < grid.ny / 2; ++ky)
    for (Index kx = -grid.nx / 2; kx < grid.nx / 2; ++kx) {
      if ((kx == 0 && ky == 0) || kx == -grid.nx / 2 || ky == -grid.ny / 2) continue;
      const Real qx = 2 * std::numbers::pi * static_cast<Real>(kx) / grid.lx;
      const Real qy = 2 * std::numbers::pi * static_cast<Real>(ky) / grid.ly;
      const Real q = std::hypot(qx, qy);
      if (q > qs) continue;
      const Real c = q < psd.qr ? 1 : std::pow(q / psd.qr, -2 * (1 + psd.hurst));
      c_sum += c;
      c_qx2 += qx * qx * c;
      c_qy2 += qy * qy * c;
      c_qx4 += qx * qx * qx * qx * c;
      c_qy4 += qy * qy * qy * qy * c;
    }
  const Real s2 = psd.sigma * psd.sigma;
  SpectralMoments m{};
  m.m0 = s2;
  m.m2x = s2 * c_qx2 / c_sum;
  m.m2y = s2 * c_qy2 / c_sum;
  m.m4x = s2 * c_qx4 / c_sum;
  m.m4y = s2 * c_qy4 / c_sum;
  return m;
}

TEST(PaperSurfaces, SurfaceAReproducesTable2ForAnySeed) {
  for (const std::uint64_t seed : {1ULL, 2ULL, 12345ULL, 0xdeadbeefULL}) {
    const Surface a = generate_surface(paper::grid(), paper::surface_a(), seed, 2);
    expect_table2(spectral_moments(a), {0.250, 0.0110, 0.0446}, "surface A");
  }
}

TEST(PaperSurfaces, SurfaceBWithQsAtNyquistReproducesTable2) {
  for (const std::uint64_t seed : {1ULL, 7ULL, 99ULL}) {
    const Surface b = generate_surface(paper::grid(), paper::surface_b(), seed, 2);
    expect_table2(spectral_moments(b), {1.00, 0.0391, 0.0992}, "surface B");
  }
}

TEST(PaperSurfaces, SurfaceBWithThePrintedQsDoesNotReproduceTable2) {
  // Table 1 prints qs = 3.00e6 1/m for surface B; that cut gives m2 = 0.0337 and m4 = 0.0492 um^-2
  // (docs/theory.md section 2), not Table 2's 0.0391 and 0.0992. This records the paper's inconsistency.
  const Surface b = generate_surface(paper::grid(), paper::surface_b_printed_qs(), 1, 2);
  const SpectralMoments m = spectral_moments(b);
  EXPECT_NEAR(m.m0 / (um * um), 1.00, tolerance::table2);
  EXPECT_NEAR(m.m2x, 0.0337, tolerance::table2 * 0.0337);
  EXPECT_NEAR(m.m4x * um * um, 0.0492, tolerance::table2 * 0.0492);
  EXPECT_GT(std::abs(m.m2x - 0.0391), 0.1 * 0.0391);  // far outside Table 2's value
}

TEST(PaperSurfaces, LatticeMomentsEqualAnIndependentSum) {
  // The generator's moments (through the surface and spectral_moments) against the lattice sum written out
  // above; for B with the printed qs, also against the independent values m2 = 0.033668, m4 =
  // 0.049194 (six digits). Tolerance 1e-10 relative: a 64k-term sum and one FFT of the heights in double
  // (measured below 1e-12). Rejects the Nyquist row or column kept (their modes lie inside the circle of
  // radius qs for A and B), a square cut instead of a circle, or H or qr off in the third digit, which the 1
  // % of Table 2 could not see.
  for (const auto& [psd, what] : {std::pair<SelfAffinePsd, const char*>{paper::surface_a(), "A"},
                                  {paper::surface_b(), "B"},
                                  {paper::surface_b_printed_qs(), "B, printed qs"}}) {
    const SpectralMoments m = spectral_moments(generate_surface(paper::grid(), psd, 5, 2));
    const SpectralMoments e = lattice_sum(psd);
    EXPECT_NEAR(m.m0, e.m0, 1e-10 * e.m0) << what;
    EXPECT_NEAR(m.m2x, e.m2x, 1e-10 * e.m2x) << what;
    EXPECT_NEAR(m.m2y, e.m2y, 1e-10 * e.m2y) << what;
    EXPECT_NEAR(m.m4x, e.m4x, 1e-10 * e.m4x) << what;
    EXPECT_NEAR(m.m4y, e.m4y, 1e-10 * e.m4y) << what;
  }
  // The six printed digits: half a unit of the last is 5e-7; allow 1e-6.
  const SpectralMoments printed = lattice_sum(paper::surface_b_printed_qs());
  EXPECT_NEAR(printed.m2x, 0.033668, 1e-6);
  EXPECT_NEAR(printed.m4x * um * um, 0.049194, 1e-6);
}

TEST(Generation, MomentsDoNotDependOnTheSeed) {
  // Deterministic modulus, random phase: the lattice moments are the same numbers for every seed.
  const SpectralMoments one = spectral_moments(generate_surface(paper::grid(), paper::surface_a(), 1));
  const SpectralMoments two = spectral_moments(generate_surface(paper::grid(), paper::surface_a(), 2));
  // Only the FFT's round-off differs between the two.
  EXPECT_NEAR(one.m2x, two.m2x, tolerance::fft_round_off * one.m2x);
  EXPECT_NEAR(one.m4y, two.m4y, tolerance::fft_round_off * one.m4y);
}

TEST(Generation, RmsHeightIsSigmaAndTheMeanIsZero) {
  const Surface a = generate_surface(paper::grid(), paper::surface_a(), 3);
  // Normalised on the lattice (sum C dq^2 = sigma^2), so Sq = sigma up to one FFT's round-off.
  EXPECT_NEAR(a.rms_height(), 0.5 * um, tolerance::fft_round_off * um);
  EXPECT_NEAR(a.mean_height(), 0.0, tolerance::fft_round_off * um);
}

TEST(Generation, TheSurfaceCarriesExactlyTheGeneratedCoefficients) {
  // Transforming the heights back must return the coefficients: proves the phases are Hermitian
  // (phi_{-k} = -phi_k) on the self-conjugate kx = 0 column, where a slip would be lost silently by c2r.
  const Grid grid{.nx = 64, .ny = 40, .lx = 64e-6, .ly = 50e-6, .periodic = true};
  const SelfAffinePsd psd{.sigma = 1e-6, .hurst = 0.7, .qr = 2e5, .qs = std::nullopt, .anisotropy = 1};
  const SpectrumMap hhat = generate_coefficients(grid, psd, 42);
  const FourierCoefficients back = fourier_coefficients(generate_surface(grid, psd, 42), Window::none);
  EXPECT_LT((back.hhat - hhat).abs().maxCoeff(), tolerance::fft_round_off * hhat.abs().maxCoeff());
}

TEST(Generation, SameSeedIsBitIdenticalForOneAndTwoThreads) {
  const Surface one = generate_surface(paper::grid(), paper::surface_a(), 2024, 1);
  const Surface two = generate_surface(paper::grid(), paper::surface_a(), 2024, 2);
  EXPECT_TRUE((one.heights() == two.heights()).all());  // bit for bit, not approximately
  const Surface fine_one = refine(one, 512, 512, 1);
  const Surface fine_two = refine(one, 512, 512, 2);
  EXPECT_TRUE((fine_one.heights() == fine_two.heights()).all());
  const Surface other = generate_surface(paper::grid(), paper::surface_a(), 2025, 2);
  EXPECT_FALSE((one.heights() == other.heights()).all());
}

TEST(Refinement, KeepsMomentsAndTheHeightsAtTheOriginalNodes) {
  const Surface a = generate_surface(paper::grid(), paper::surface_a(), 5, 2);
  const SpectralMoments coarse = spectral_moments(a, 2);
  for (const Index n : {512, 1024}) {
    const Surface fine = refine(a, n, n, 2);
    ASSERT_EQ(fine.nx(), n);
    EXPECT_DOUBLE_EQ(fine.grid().lx, a.grid().lx);
    const SpectralMoments m = spectral_moments(fine, 2);
    EXPECT_NEAR(m.m0, coarse.m0, tolerance::refined_moments * coarse.m0) << n;
    EXPECT_NEAR(m.m2x, coarse.m2x, tolerance::refined_moments * coarse.m2x) << n;
    EXPECT_NEAR(m.m4x, coarse.m4x, tolerance::refined_moments * coarse.m4x) << n;
    EXPECT_NEAR(m.m2y, coarse.m2y, tolerance::refined_moments * coarse.m2y) << n;
    EXPECT_NEAR(m.m4y, coarse.m4y, tolerance::refined_moments * coarse.m4y) << n;
    const Index stride = n / 256;
    const HeightMap at_nodes = Eigen::Map<const HeightMap, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>(
        fine.heights().data(), 256, 256, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(n * stride, stride));
    // Relative to the heights' scale (Sq): pointwise relative error is meaningless at zero crossings.
    EXPECT_LT((at_nodes - a.heights()).abs().maxCoeff(), tolerance::refined_nodes * a.rms_height()) << n;
  }
}

TEST(Refinement, SplitsNyquistContentSoThatAnyPeriodicSurfaceKeepsItsNodes) {
  // A checkerboard lives entirely on the Nyquist mode; white noise has some there too. Non-square grids.
  const Grid grid{.nx = 6, .ny = 4, .lx = 6e-6, .ly = 4e-6, .periodic = true};
  HeightMap h(4, 6);
  for (Index iy = 0; iy < 4; ++iy)
    for (Index ix = 0; ix < 6; ++ix)
      h(iy, ix) = ((ix + iy) % 2 ? 1.0 : -1.0) + 0.1 * std::sin(ix * iy + 1.0);
  const Surface coarse(grid, h);
  const Surface fine = refine(coarse, 18, 12);
  for (Index iy = 0; iy < 4; ++iy)
    for (Index ix = 0; ix < 6; ++ix)
      EXPECT_NEAR(fine.heights()(3 * iy, 3 * ix), h(iy, ix), tolerance::fft_round_off) << ix << ", " << iy;
  EXPECT_NEAR(fine.mean_height(), coarse.mean_height(), tolerance::fft_round_off);
}

TEST(Refinement, RefusesANonPeriodicSurfaceAndACoarserGrid) {
  const Surface a = generate_surface(paper::grid(), paper::surface_a(), 1);
  EXPECT_THROW(refine(a.with_periodic(false), 512, 512), Error);
  EXPECT_THROW(refine(a, 128, 256), Error);
}

TEST(Anisotropy, GivesTheRequestedSlopeRatio) {
  const Grid grid{.nx = 256, .ny = 256, .lx = 200e-6, .ly = 200e-6, .periodic = true};
  for (const Real ratio : {4.0, 0.25, 10.0}) {
    SelfAffinePsd psd = paper::surface_a();
    psd.anisotropy = ratio;
    const SpectralMoments m = spectral_moments(generate_surface(grid, psd, 8, 2));
    // The lattice samples the elliptical spectrum and its cut: the issue allows 2 %.
    EXPECT_NEAR(m.m2x / m.m2y, ratio, tolerance::anisotropy_ratio * ratio) << ratio;
  }
}

TEST(Anisotropy, WorksOnNonSquareGridsWithRectangularPixels) {
  const Grid grid{.nx = 256, .ny = 128, .lx = 200e-6, .ly = 150e-6, .periodic = true};
  SelfAffinePsd psd = paper::surface_a();
  psd.anisotropy = 3;
  const SpectralMoments m = spectral_moments(generate_surface(grid, psd, 8, 2));
  EXPECT_NEAR(m.m2x / m.m2y, 3.0, tolerance::anisotropy_ratio * 3.0);
}

// A lateral size of 1e-300 m puts the whole lattice 1e300 times above qr = 1e5 1/m: every mode's power
// underflows. The message names the lattice's lowest wavevector, qr and the way out, not only "no mode".
TEST(Generation, ALatticeFarAboveTheRollOffNamesTheConflict) {
  const Grid grid{.nx = 64, .ny = 64, .lx = 1e-300, .ly = 1e-300, .periodic = true};
  const SelfAffinePsd psd{.sigma = 1e-6, .hurst = 0.8, .qr = 1e5, .qs = std::nullopt};
  try {
    generate_surface(grid, psd, 1);
    ADD_FAILURE() << "generated a surface whose every mode underflows";
  } catch (const Error& e) {
    const std::string message = e.what();
    for (const char* part : {"lowest wavevector 2 pi/L = 6.28319e+300 1/m", "qr = 100000 1/m",
                             "below double precision", "choose qr near or above 2 pi/L"})
      EXPECT_NE(message.find(part), std::string::npos) << message;
  }
}

TEST(Generation, RefusesParametersOutsideTheirRange) {
  const Grid grid = paper::grid();
  auto expect_refused = [&](SelfAffinePsd psd, const char* word) {
    try {
      generate_surface(grid, psd, 1);
      ADD_FAILURE() << "accepted bad " << word;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  SelfAffinePsd psd = paper::surface_a();
  psd.sigma = -1e-6;
  expect_refused(psd, "sigma");
  psd = paper::surface_a();
  psd.hurst = 1.5;
  expect_refused(psd, "hurst");
  psd = paper::surface_a();
  psd.qr = std::nan("");
  expect_refused(psd, "qr");
  psd = paper::surface_a();
  psd.qs = 1e7;  // above Nyquist pi/dx = 4.02e6
  expect_refused(psd, "qs");
  psd = paper::surface_a();
  psd.anisotropy = 0;
  expect_refused(psd, "anisotropy");
}

}  // namespace
}  // namespace contactbench
