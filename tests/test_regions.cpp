// Regions and levelling of a measured topography (docs/formats.md "regions and levelling"): crop (pixels,
// metres, the largest fully measured rectangle), row alignment, polynomial levelling of degree 2, applied in
// that order and recorded in what a read reports.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"
#include "test_constants.hpp"
#include "test_folder.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

using testing::nan;

TEST(Crop, ParsesTheThreeKindsAndRefusesTheRest) {
  ASSERT_TRUE(parse_crop("measured"));
  const auto pixels = parse_crop("px:1,2,3,4");
  ASSERT_TRUE(pixels);
  EXPECT_EQ(pixels->kind, CropSpec::Kind::pixels);
  EXPECT_EQ(to_string(*pixels), "px:1,2,3,4");
  const auto metres = parse_crop("m:1e-6, 0, 2.5e-6, 1e-6");
  ASSERT_TRUE(metres);
  EXPECT_EQ(to_string(*metres), "m:1e-06,0,2.5e-06,1e-06");
  for (const char* bad : {"", "px:1,2,3", "px:1.5,0,2,2", "px:0,0,0,2", "m:-1,0,1,1", "mm:0,0,1,1", "all"})
    EXPECT_FALSE(parse_crop(bad)) << bad;
}

TEST(Crop, TheLargestMeasuredRectangleIsFound) {
  // 6 x 5, invalid points (X) around a 3 x 3 block of valid ones (and a longer but thinner 5 x 1 strip):
  //   row 0: . . . . . X     valid run of 5 (area 5)
  //   row 1: X X X X X X
  //   row 2: X . . . X X     the 3 x 3 block: columns 1-3, rows 2-4 (area 9)
  //   row 3: . . . . X .
  //   row 4: X . . . X X
  const std::string rows[5] = {".....X", "XXXXXX", "X...XX", "....X.", "X...XX"};
  std::vector<double> values;
  for (const std::string& row : rows)
    for (const char c : row)
      values.push_back(c == 'X' ? nan : 1.0);
  Index nx = 6, ny = 5;
  double lx = 6e-6, ly = 5e-6;
  const formats::CropResult kept =
      formats::crop_values("mask", values, nx, ny, lx, ly, *parse_crop("measured"));
  EXPECT_EQ(kept.x0, 1);
  EXPECT_EQ(kept.y0, 2);
  EXPECT_EQ(nx, 3);
  EXPECT_EQ(ny, 3);
  // Sizes stay count x step (one rounding each way).
  EXPECT_NEAR(lx, 3e-6, 1e-15 * 3e-6);
  EXPECT_NEAR(ly, 3e-6, 1e-15 * 3e-6);
  for (const double v : values)
    EXPECT_EQ(v, 1.0);
}

TEST(Crop, MetresSelectThePointsInsideAndARectangleOutsideIsRefused) {
  std::vector<double> values(10 * 4);
  for (std::size_t k = 0; k < values.size(); ++k)
    values[k] = static_cast<double>(k);
  Index nx = 10, ny = 4;
  double lx = 10e-6, ly = 4e-6;  // step 1 um: points at 0, 1, ..., 9 um
  // [2.5, 6.5) um: the points at 3, 4, 5, 6 um; [1, 3) um in y: rows 1 and 2.
  std::vector<double> copy = values;
  formats::crop_values("grid", copy, nx, ny, lx, ly, *parse_crop("m:2.5e-6,1e-6,4e-6,2e-6"));
  EXPECT_EQ(nx, 4);
  EXPECT_EQ(ny, 2);
  EXPECT_EQ(copy.front(), 13.0);  // row 1, column 3
  EXPECT_EQ(copy.back(), 26.0);   // row 2, column 6
  Index nx2 = 10, ny2 = 4;
  double lx2 = 10e-6, ly2 = 4e-6;
  try {
    formats::crop_values("grid.txt", values, nx2, ny2, lx2, ly2, *parse_crop("px:8,0,5,2"));
    ADD_FAILURE() << "a crop beyond the grid was accepted";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("grid.txt: crop px:8,0,5,2 selects columns 8 to 12"),
              std::string::npos)
        << error.what();
  }
}

TEST(RowAlignment, EachRowLosesItsOwnOffsetOrLine) {
  // Rows with their own offsets and tilts on top of a column profile c(x): mean alignment leaves c(x) - its
  // mean plus the tilts; linear alignment leaves c(x) minus its own line, the same in every row.
  HeightMap h(3, 5);
  const double profile[5] = {0, 2, -1, 3, 1};
  for (Index y = 0; y < 3; ++y)
    for (Index x = 0; x < 5; ++x)
      h(y, x) = profile[x] + 10.0 * y + 0.5 * y * (x - 2.0);
  HeightMap linear = h;
  align_rows(linear, RowAlignment::linear);
  for (Index x = 0; x < 5; ++x) {
    // Exact to a few roundings of sums of five small integers and halves.
    EXPECT_NEAR(linear(0, x), linear(2, x), 1e-13);
    EXPECT_NEAR(linear(1, x), linear(0, x), 1e-13);
  }
  HeightMap median = h;
  align_rows(median, RowAlignment::median);
  // Row 0 is the profile itself: its median is 1.
  for (Index x = 0; x < 5; ++x)
    EXPECT_EQ(median(0, x), profile[x] - 1.0);
  HeightMap mean = h;
  align_rows(mean, RowAlignment::mean);
  for (Index y = 0; y < 3; ++y)
    EXPECT_NEAR(mean.row(y).mean(), 0.0, 1e-14);
}

TEST(Levelling, QuadraticRemovesAnyPolynomialOfDegreeTwoAndPlaneDoesNot) {
  const Grid grid{17, 11, 17e-6, 11e-6, false};
  HeightMap h(11, 17);
  for (Index y = 0; y < 11; ++y)
    for (Index x = 0; x < 17; ++x)
      h(y, x) = 1e-6 * (0.3 + 0.2 * x - 0.1 * y + 0.05 * x * x - 0.02 * x * y + 0.03 * y * y);
  HeightMap quadratic = h;
  level_heights(quadratic, grid, Levelling::quadratic);
  // Left over: round-off of a 6 x 6 solve on heights of ~1e-5 m.
  EXPECT_LT(quadratic.abs().maxCoeff(), 1e-18);
  HeightMap plane = h;
  level_heights(plane, grid, Levelling::plane);
  EXPECT_GT(plane.abs().maxCoeff(), 1e-7);
}

TEST(HarmonicFill, MoreInvalidPointsThanItsBoundAreRefusedAtOnce) {
  // 2100 x 2100 points, all invalid but one row: 4407900 to fill, beyond the bound of 4194304; refused before
  // any level is built (this test takes milliseconds; the fill would take seconds and a gigabyte).
  constexpr int n = 2100;
  std::vector<double> values(static_cast<std::size_t>(n) * n, nan);
  for (int x = 0; x < n; ++x)
    values[static_cast<std::size_t>(x)] = 1e-9;
  try {
    fill_invalid_points(values, n, n, FillMethod::harmonic);
    ADD_FAILURE() << "filled more points than the bound";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("harmonic fill of 4407900 invalid points refused"),
              std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("--crop measured"), std::string::npos) << error.what();
  }
}

class RegionFiles : public testing::FolderTest {
 protected:
  RegionFiles() : FolderTest("contactbench_regions_") {}
};

TEST_F(RegionFiles, ASurMeasuredOverPartOfItsGridReadsWithoutFilling) {
  // sur-3.sur: 233009 of 262144 points unmeasured (data/formats/README.md). Cropped to its largest measured
  // rectangle it reads with fill none, and the reading records the rectangle.
  TopographyReadOptions options;
  options.crop = parse_crop("measured");
  const TopographyReading r = read_topography_reading(CB_DATA_DIR "/formats/sur-3.sur", options);
  EXPECT_EQ(r.invalid_points, 0);
  EXPECT_EQ(r.crop, "measured (columns 61 to 249, rows 229 to 280)");
  EXPECT_EQ(r.surface.nx(), 189);
  EXPECT_EQ(r.surface.ny(), 52);
  EXPECT_FALSE(r.surface.grid().periodic);
}

TEST_F(RegionFiles, TheOrderIsCropThenFillThenRowsThenLevel) {
  // A 4 x 3 matrix (in um) with one invalid point outside the crop: cropped first, nothing is left to fill;
  // then each row's mean goes, then the plane, and the reading says so.
  const fs::path file = write("m.txt", "1 2 3 NaN\n4 6 8 1\n9 9 9 1\n");
  TopographyReadOptions options;
  options.lx = 4e-6;
  options.unit = "um";
  options.crop = parse_crop("px:0,0,3,3");
  options.align_rows = RowAlignment::mean;
  options.level = Levelling::plane;
  const TopographyReading r = read_topography_reading(file, options);
  EXPECT_EQ(r.invalid_points, 0);
  EXPECT_EQ(r.crop, "px:0,0,3,3 (columns 0 to 2, rows 0 to 2)");
  EXPECT_EQ(r.align_rows, RowAlignment::mean);
  EXPECT_EQ(r.level, Levelling::plane);
  // Rows after their means: (-1, 0, 1) um, (-2, 0, 2) um, (0, 0, 0); the plane then takes the mean slope
  // along x, 1 um per step: left (0, 0, 0), (-1, 0, 1), (1, 0, -1) um, less the y-slope (zero by symmetry).
  const double expected[3][3] = {{0, 0, 0}, {-1e-6, 0, 1e-6}, {1e-6, 0, -1e-6}};
  for (Index y = 0; y < 3; ++y)
    for (Index x = 0; x < 3; ++x)
      EXPECT_NEAR(r.surface.heights()(y, x), expected[y][x], 1e-21) << y << " " << x;
}

}  // namespace
}  // namespace contactbench
