// The instrument formats added for measured files (docs/formats.md "al3d", "nid", "mi"): each sample of
// data/formats/ read to the reference values of data/formats/README.md (sizes, units, rms, channels, invalid
// points). Tolerances: a reference printed with ten significant digits is compared to 1e-9 relative; one
// printed with fewer, to half a unit of its last digit (said where it applies).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

using testing::kFormatSamples;

void expect_relative(double value, double reference, double tolerance, const std::string& what) {
  EXPECT_NEAR(value, reference, tolerance * std::abs(reference)) << what;
}

TopographyReading read_channel(const fs::path& file, const std::string& channel) {
  TopographyReadOptions options;
  options.channel = channel;
  return read_topography_reading(file, options);
}

// The rms about the mean of each line along x (a row), then the root of their mean square: the "profile rms
// along x" of the README; along y the same over columns.
double profile_rms(const HeightMap& h, bool along_x) {
  const Index lines = along_x ? h.rows() : h.cols();
  double sum = 0;
  for (Index k = 0; k < lines; ++k) {
    const Eigen::ArrayXd line = along_x ? Eigen::ArrayXd(h.row(k).transpose()) : Eigen::ArrayXd(h.col(k));
    sum += (line - line.mean()).square().mean();
  }
  return std::sqrt(sum / static_cast<double>(lines));
}

TEST(InstrumentSamples, AliconaAl3d) {
  const TopographyReading r = read_topography_reading(kFormatSamples / "al3d-1.al3d");
  EXPECT_EQ(r.format, TopographyFormat::alicona);
  EXPECT_EQ(r.channels, (std::vector<std::string>{"depth"}));
  EXPECT_EQ(r.invalid_points, 0);
  EXPECT_EQ(r.surface.nx(), 200);
  EXPECT_EQ(r.surface.ny(), 296);
  // n x the pixel size: one rounding of the product.
  expect_relative(r.surface.grid().lx, 8.76054e-05, 1e-15, "lx");
  expect_relative(r.surface.grid().ly, 1.29655992e-04, 1e-15, "ly");
  // The README's al3d values were evidently summed in single precision from the float32 data: a
  // double-precision sum (here, and independently in plain Python: rms 7.688265843e-06, rows 3.915730014e-06,
  // columns 6.620846789e-06) differs from them by 3.3e-8, 2.5e-7 and 3e-8 relative, a few float32 roundings
  // (eps 6e-8) over 59200 squares. Hence 1e-7 and, for the rows, 5e-7.
  expect_relative(r.surface.rms_height(), 7.6882661e-06, 1e-7, "rms");
  // The orientation: rows run along x; swapped, the two would differ by 70 %.
  expect_relative(profile_rms(r.surface.heights(), true), 3.915731e-06, 5e-7, "profile rms along x");
  expect_relative(profile_rms(r.surface.heights(), false), 6.620847e-06, 1e-7, "profile rms along y");
}

TEST(InstrumentSamples, NanosurfNidEveryDataSet) {
  const fs::path file = kFormatSamples / "nid-1.nid";
  const TopographyReading first = read_topography_reading(file);
  EXPECT_EQ(first.format, TopographyFormat::nanosurf);
  EXPECT_EQ(first.channels,
            (std::vector<std::string>{"Deflection (Scan forward)", "Z-Axis (Scan forward)",
                                      "Friction force (Scan forward)", "Z-AxisSensor (Scan forward)",
                                      "Deflection (Scan backward)", "Z-Axis (Scan backward)",
                                      "Friction force (Scan backward)", "Z-AxisSensor (Scan backward)"}));
  // The first height channel: Deflection is a force (N).
  EXPECT_EQ(first.channel, "Z-Axis (Scan forward)");
  EXPECT_EQ(first.surface.nx(), 256);
  EXPECT_EQ(first.surface.ny(), 256);
  EXPECT_EQ(first.surface.grid().lx, 2e-05);
  EXPECT_EQ(first.surface.grid().ly, 2e-05);
  expect_relative(first.surface.rms_height(), 2.395896707e-07, 1e-9, "forward Z-Axis");
  expect_relative(read_channel(file, "Z-AxisSensor (Scan forward)").surface.rms_height(), 3.026701737e-07,
                  1e-9, "forward Z-AxisSensor");
  expect_relative(read_channel(file, "5").surface.rms_height(), 2.394186769e-07, 1e-9, "backward Z-Axis");
  expect_relative(read_channel(file, "Z-AxisSensor (Scan backward)").surface.rms_height(), 3.029781629e-07,
                  1e-9, "backward Z-AxisSensor");
  EXPECT_THROW(read_channel(file, "Deflection (Scan forward)"), InputError);
}

TEST(InstrumentSamples, AgilentMiBuffersScaleAndLineOrder) {
  const fs::path file = kFormatSamples / "mi-1.mi";
  const TopographyReading r = read_topography_reading(file);
  EXPECT_EQ(r.format, TopographyFormat::agilent_mi);
  EXPECT_EQ(r.channels,
            (std::vector<std::string>{"Topography", "Deflection", "Friction trace", "Friction retrace"}));
  EXPECT_EQ(r.channel, "Topography");
  EXPECT_EQ(r.unit, "um");
  EXPECT_EQ(r.surface.nx(), 256);
  EXPECT_EQ(r.surface.ny(), 256);
  EXPECT_EQ(r.surface.grid().lx, 2.0000000000000002e-05);
  const HeightMap& h = r.surface.heights();
  expect_relative(r.surface.mean_height(), -5.588049271e-07, 1e-9, "mean");
  expect_relative(h.minCoeff(), -6.299615479e-07, 1e-9, "min");
  expect_relative(h.maxCoeff(), -4.643220520e-07, 1e-9, "max");
  // 3.3215426e-08: eight digits, half a unit of the last is 1.6e-8 relative.
  expect_relative(r.surface.rms_height(), 3.3215426e-08, 1.6e-8, "rms");
  // scanUp TRUE: y = 0 is the file's last line, whose first point SurfaceTopography's test_mi.py gives as
  // -0.498690 um (six digits: 1e-6 relative).
  expect_relative(h(0, 0), -0.498690e-6, 1e-6, "h(x0, y0)");
  EXPECT_THROW(read_channel(file, "Deflection"), InputError);
}

}  // namespace
}  // namespace contactbench
