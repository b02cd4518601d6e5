// The FFT engine: conventions, round trips, reproducibility across thread counts, thread-safe planning.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <thread>
#include <vector>

#include "contactbench/core/fft.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

HeightMap white_noise(Index nx, Index ny, unsigned seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<Real> normal;
  HeightMap h(ny, nx);
  for (Index i = 0; i < h.size(); ++i)
    h.data()[i] = normal(random);
  return h;
}

TEST(RealFft2d, ForwardOfOneModeIsItsCoefficientTimesThePointCount) {
  // h = cos(2 pi (3 x / Lx + 2 y / Ly)) has coefficient 1/2 at k = (3, 2) and its conjugate at -k.
  const Index nx = 16, ny = 12;
  HeightMap h(ny, nx);
  for (Index iy = 0; iy < ny; ++iy)
    for (Index ix = 0; ix < nx; ++ix)
      h(iy, ix) = std::cos(2 * std::numbers::pi * (3.0 * ix / nx + 2.0 * iy / ny));
  RealFft2d fft(nx, ny);
  SpectrumMap c;
  fft.forward(h, c);
  c /= static_cast<Real>(nx * ny);
  // Round-off of a 192-point transform of O(1) values: far below fft_round_off.
  EXPECT_NEAR(c(2, 3).real(), 0.5, tolerance::fft_round_off);
  EXPECT_NEAR(c(2, 3).imag(), 0.0, tolerance::fft_round_off);
  c(2, 3) = 0;
  EXPECT_LT(c.abs().maxCoeff(), tolerance::fft_round_off);
}

TEST(RealFft2d, RoundTripGivesThePointCountTimesTheInput) {
  for (auto [nx, ny] : {std::pair<Index, Index>{64, 64}, {45, 30}, {1, 17}, {33, 1}}) {
    const HeightMap h = white_noise(nx, ny, 7);
    RealFft2d fft(nx, ny, 2);
    SpectrumMap c;
    HeightMap back;
    fft.forward(h, c);
    fft.backward(c, back);
    back /= static_cast<Real>(nx * ny);
    // Unit-variance noise through one FFT pair: errors of a few 1e-16 times log2(n).
    EXPECT_LT((back - h).abs().maxCoeff(), tolerance::fft_round_off) << nx << " x " << ny;
  }
}

TEST(ReproducibleInverseFft2d, AgreesWithTheThreadedPlan) {
  for (auto [nx, ny] : {std::pair<Index, Index>{64, 48}, {37, 50}, {16, 1}}) {
    RealFft2d fft(nx, ny, 2);
    SpectrumMap c;
    fft.forward(white_noise(nx, ny, 3), c);
    HeightMap expected, reproducible;
    fft.backward(c, expected);
    ReproducibleInverseFft2d(nx, ny).backward(c, reproducible, 2);
    // Same sum, different order of operations: agreement to round-off relative to the values' size.
    EXPECT_LT((expected - reproducible).abs().maxCoeff(),
              tolerance::fft_round_off * expected.abs().maxCoeff())
        << nx << " x " << ny;
  }
}

TEST(ReproducibleInverseFft2d, IsBitIdenticalForAnyThreadCount) {
  const Index nx = 100, ny = 70;  // sizes that leave partial chunks of lines
  RealFft2d fft(nx, ny);
  SpectrumMap c;
  fft.forward(white_noise(nx, ny, 11), c);
  ReproducibleInverseFft2d inverse(nx, ny);
  HeightMap one, two, three;
  inverse.backward(c, one, 1);
  inverse.backward(c, two, 2);
  inverse.backward(c, three, 3);
  // Bit for bit: the promise is exact equality, not closeness.
  EXPECT_TRUE((one == two).all());
  EXPECT_TRUE((one == three).all());
}

TEST(RealFft2d, PlansCanBeMadeFromManyThreadsAtOnce) {
  const HeightMap h = white_noise(32, 24, 5);
  std::vector<Real> sums(6, 0);
  std::vector<std::thread> workers;
  for (std::size_t t = 0; t < sums.size(); ++t)
    workers.emplace_back([&, t] {
      for (int repeat = 0; repeat < 20; ++repeat) {
        RealFft2d fft(32, 24);
        SpectrumMap c;
        fft.forward(h, c);
        sums[t] = c.abs2().sum();
      }
    });
  for (auto& worker : workers)
    worker.join();
  // Parseval: sum |H_k|^2 over the half lattice is a fixed number; every thread must get it exactly.
  for (std::size_t t = 1; t < sums.size(); ++t)
    EXPECT_EQ(sums[t], sums[0]);
}

TEST(CachedFft, ReturnsTheSamePlanForTheSameShape) {
  RealFft2d& first = cached_fft(20, 10, 1);
  RealFft2d& again = cached_fft(20, 10, 1);
  RealFft2d& other = cached_fft(10, 20, 1);
  EXPECT_EQ(&first, &again);
  EXPECT_NE(&first, &other);
}

}  // namespace
}  // namespace contactbench
