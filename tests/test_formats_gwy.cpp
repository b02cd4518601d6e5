// Gwyddion's native .gwy (core/formats/gwy.cpp, gwy_writer.cpp): the round trip is bit for bit; the written
// bytes follow the layout of Gwyddion's user guide ("Format of Gwyddion Files"), walked here independently of
// the reader; a hand-built file with two channels, a unit prefix and a mask reads right; cut files are
// refused.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/md5.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/topography_io.hpp"
#include "height_bits.hpp"
#include "test_folder.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Serialization by the user guide, for files the tests build by hand.
template <typename T>
std::string little(T value) {
  std::string out(sizeof(T), '\0');
  std::memcpy(out.data(), &value, sizeof(T));  // the test machines are little-endian (x86-64, arm64)
  return out;
}
std::string object(const std::string& type, const std::string& components) {
  return type + '\0' + little(static_cast<std::uint32_t>(components.size())) + components;
}
std::string component(const std::string& name, char type, const std::string& value) {
  return name + '\0' + type + value;
}
std::string unit(const std::string& text) {
  return object("GwySIUnit", component("unitstr", 's', text + '\0'));
}
std::string field(int nx, int ny, double lx, double ly, const std::string& xy, const std::string& z,
                  const std::vector<double>& values) {
  std::string data = little(static_cast<std::uint32_t>(values.size()));
  for (const double v : values)
    data += little(v);
  return object("GwyDataField",
                component("xres", 'i', little<std::int32_t>(nx)) +
                    component("yres", 'i', little<std::int32_t>(ny)) + component("xreal", 'd', little(lx)) +
                    component("yreal", 'd', little(ly)) + component("si_unit_xy", 'o', unit(xy)) +
                    component("si_unit_z", 'o', unit(z)) + component("data", 'D', data));
}

class GwyFiles : public testing::FolderTest {
 protected:
  GwyFiles() : FolderTest("contactbench_gwy_") {}
};

TEST_F(GwyFiles, RoundTripIsBitForBitInHeightsAndSizes) {
  const Grid grid{48, 40, 1.7e-4, 1.3e-4, false};
  const Surface surface = generate_surface(grid, SelfAffinePsd{0.5e-6, 0.7, 1e5, std::nullopt, 1.0}, 7, 1);
  const fs::path file = folder_ / "surface.gwy";
  write_topography(file, surface);
  EXPECT_EQ(detect_topography_format(file), TopographyFormat::gwy);
  const TopographyReading copy = read_topography_reading(file);
  EXPECT_EQ(copy.channels, (std::vector<std::string>{"height"}));
  EXPECT_EQ(testing::bits_of(copy.surface.heights()), testing::bits_of(surface.heights()));
  // The sizes are stored as the doubles themselves: equal, not near.
  EXPECT_EQ(copy.surface.grid().lx, grid.lx);
  EXPECT_EQ(copy.surface.grid().ly, grid.ly);
  EXPECT_EQ(copy.surface.nx(), 48);
  EXPECT_EQ(copy.surface.ny(), 40);
}

TEST_F(GwyFiles, WrittenBytesFollowThePublicLayout) {
  // 2 x 1 heights: every byte of the file accounted for, in the order the user guide gives.
  const Surface surface(Grid{2, 1, 2e-6, 1e-6, false}, HeightMap{{1.5e-9, -2.25e-9}});
  const fs::path file = folder_ / "tiny.gwy";
  write_topography(file, surface);
  const std::string unit_m = unit("m");
  const std::string data = little<std::uint32_t>(2) + little(1.5e-9) + little(-2.25e-9);
  const std::string field_bytes =
      object("GwyDataField", component("xres", 'i', little<std::int32_t>(2)) +
                                 component("yres", 'i', little<std::int32_t>(1)) +
                                 component("xreal", 'd', little(2e-6)) +
                                 component("yreal", 'd', little(1e-6)) + component("xoff", 'd', little(0.0)) +
                                 component("yoff", 'd', little(0.0)) + component("si_unit_xy", 'o', unit_m) +
                                 component("si_unit_z", 'o', unit_m) + component("data", 'D', data));
  const std::string expected =
      "GWYP" + object("GwyContainer", component("/0/data", 'o', field_bytes) +
                                          component("/0/data/title", 's', std::string("height") + '\0'));
  EXPECT_EQ(bytes_of(file), expected);
}

TEST_F(GwyFiles, ChannelsUnitsAndMaskOfAHandBuiltFile) {
  // Channel 0: a voltage (not a height); channel 1: heights in nm over 3 x 2 points of 1 um, with a mask
  // marking the point (x 1, y 1) invalid.
  const std::string voltage = field(3, 2, 3e-6, 2e-6, "m", "V", {0, 0, 0, 0, 0, 0});
  const std::string heights = field(3, 2, 3e-6, 2e-6, "m", "nm", {1, 2, 3, 4, 5, 6});
  const std::string mask = field(3, 2, 3e-6, 2e-6, "m", "", {0, 0, 0, 0, 1, 0});
  const std::string container =
      component("/0/data", 'o', voltage) + component("/0/data/title", 's', "Bias" + std::string(1, '\0')) +
      component("/1/data", 'o', heights) +
      component("/1/data/title", 's', "Topography" + std::string(1, '\0')) + component("/1/mask", 'o', mask) +
      component("/0/meta", 'b', std::string(1, '\1'));
  const fs::path file = write("two.gwy", "GWYP" + object("GwyContainer", container));
  const std::string before = formats::md5_hex(bytes_of(file));
  TopographyReadOptions options;
  try {
    read_topography(file, options);
    ADD_FAILURE() << "read a file whose one height channel has an invalid point";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("1 of 6 points of channel 'Topography' are invalid"),
              std::string::npos)
        << error.what();
  }
  options.fill = FillMethod::mean;
  const TopographyReading reading = read_topography_reading(file, options);
  EXPECT_EQ(reading.channels, (std::vector<std::string>{"Bias", "Topography"}));
  EXPECT_EQ(reading.channel, "Topography");
  EXPECT_EQ(reading.invalid_points, 1);
  // nm to m: one rounding of the product (1e-15 relative).
  EXPECT_NEAR(reading.surface.heights()(0, 2), 3e-9, 1e-15 * 3e-9);
  EXPECT_NEAR(reading.surface.heights()(1, 0), 4e-9, 1e-15 * 4e-9);
  // The mean of 1, 2, 3, 4, 6 nm.
  EXPECT_NEAR(reading.surface.heights()(1, 1), 3.2e-9, 1e-15 * 3.2e-9);
  EXPECT_EQ(reading.surface.grid().lx, 3e-6);
  options.channel = "Bias";
  EXPECT_THROW(read_topography(file, options), InputError);
  EXPECT_EQ(formats::md5_hex(bytes_of(file)), before);
}

TEST_F(GwyFiles, CutOrCorruptFilesAreRefusedNamingTheFile) {
  const Surface surface(Grid{3, 2, 3e-6, 2e-6, false}, HeightMap{{1e-9, 2e-9, 3e-9}, {4e-9, 5e-9, 6e-9}});
  const fs::path whole = folder_ / "whole.gwy";
  write_topography(whole, surface);
  const std::string bytes = bytes_of(whole);
  // Every cut: a clean InputError, never a crash or a read of a wrong surface.
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const fs::path cut = write("cut.gwy", bytes.substr(0, length));
    try {
      read_topography(cut);
      ADD_FAILURE() << "a .gwy cut at " << length << " bytes was read";
    } catch (const InputError& error) {
      EXPECT_TRUE(std::string(error.what()).starts_with(cut.string() + ": ")) << error.what();
    }
  }
  const fs::path old = write("old.gwy", "GWYO" + bytes.substr(4));
  EXPECT_THROW(read_topography(old), InputError);
}

}  // namespace
}  // namespace contactbench
