// The Surface type's invariants and the atomic file writer.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "contactbench/core/atomic_file.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {
namespace {

const Grid kGrid{.nx = 3, .ny = 2, .lx = 3e-6, .ly = 2e-6, .periodic = false};

TEST(Surface, KeepsShapeAndSizes) {
  HeightMap h(2, 3);
  h << 1, 2, 3, 4, 5, 6;
  const Surface s(kGrid, h);
  EXPECT_EQ(s.nx(), 3);
  EXPECT_EQ(s.ny(), 2);
  EXPECT_DOUBLE_EQ(s.grid().dx(), 1e-6);
  EXPECT_DOUBLE_EQ(s.mean_height(), 3.5);
  // Sq of 1..6 about 3.5 is sqrt(35/12); the sum of six terms is exact to a few ulp.
  EXPECT_NEAR(s.rms_height(), std::sqrt(35.0 / 12.0), 1e-15);
  EXPECT_NEAR(s.centred().mean_height(), 0.0, 1e-15);
}

TEST(Surface, RefusesNonFiniteHeightsNamingThePoint) {
  HeightMap h = HeightMap::Zero(2, 3);
  h(1, 2) = std::nan("");
  try {
    Surface(kGrid, h);
    FAIL() << "a NaN height was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("(2, 1)"), std::string::npos) << e.what();
  }
}

TEST(Surface, RefusesAShapeThatDoesNotMatchTheGrid) {
  EXPECT_THROW(Surface(kGrid, HeightMap::Zero(3, 2)), Error);
}

TEST(Surface, RefusesNonPositiveSizes) {
  Grid bad = kGrid;
  bad.lx = 0;
  EXPECT_THROW(Surface(bad, HeightMap::Zero(2, 3)), Error);
  bad.lx = -1;
  EXPECT_THROW(Surface(bad, HeightMap::Zero(2, 3)), Error);
  bad = kGrid;
  bad.ly = std::numeric_limits<Real>::infinity();
  EXPECT_THROW(Surface(bad, HeightMap::Zero(2, 3)), Error);
}

TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const auto folder = std::filesystem::temp_directory_path() / "contactbench_atomic_test";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const auto target = folder / "result.txt";
  write_file_atomically(target, [](std::ostream& out) { out << "first\n"; });
  EXPECT_THROW(write_file_atomically(target,
                                     [](std::ostream& out) {
                                       out << "half";
                                       throw std::runtime_error("stopped halfway");
                                     }),
               std::runtime_error);
  std::ifstream in(target);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "first");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), {}), 1) << "a temporary was left";
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace contactbench
