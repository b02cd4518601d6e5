// Instrument formats (docs/formats.md): every sample loads with the reference grid, sizes and rms height;
// write-then-read round trips; every kind of bad file refused with a message naming it; invalid points
// refused by default and filled on request; channels; levelling.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <zip.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/formats/binary_view.hpp"
#include "contactbench/core/formats/md5.hpp"
#include "contactbench/core/formats/readers.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/topography_io.hpp"
#include "height_bits.hpp"
#include "test_constants.hpp"
#include "test_folder.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

// Samples from SurfaceTopography's test data (data/formats/README.md); the reference values there were
// computed independently from the files and agree with what that project's tests assert.
using testing::kFormatSamples;

// tolerance::measured_sq (1e-9 relative): the references are printed to ten significant digits and both
// sides scale the same stored numbers in double, so they agree to the printing.
void expect_relative(double value, double reference, const char* what) {
  EXPECT_NEAR(value, reference, tolerance::measured_sq * std::abs(reference)) << what;
}

void expect_sample(const Surface& surface, Index nx, Index ny, double lx, double ly, double rms) {
  EXPECT_EQ(surface.nx(), nx);
  EXPECT_EQ(surface.ny(), ny);
  expect_relative(surface.grid().lx, lx, "lx");
  expect_relative(surface.grid().ly, ly, "ly");
  expect_relative(surface.rms_height(), rms, "rms height");
  EXPECT_FALSE(surface.grid().periodic);
}

// rms about the mean over the valid (non-NaN) values of a channel.
double valid_rms(const formats::Channel& channel) {
  double sum = 0;
  double count = 0;
  for (const double v : channel.values)
    if (!std::isnan(v)) {
      sum += v;
      count += 1;
    }
  const double mean = sum / count;
  double squares = 0;
  for (const double v : channel.values)
    if (!std::isnan(v)) squares += (v - mean) * (v - mean);
  return std::sqrt(squares / count);
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Reading must fail with an InputError whose message begins with the file's name and contains `reason`.
void expect_refused(const fs::path& file, std::string_view reason,
                    const TopographyReadOptions& options = {}) {
  try {
    read_topography(file, options);
    ADD_FAILURE() << file << ": read without error, expected '" << reason << "'";
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with(file.string() + ": ")) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << "expected '" << reason << "' in: " << message;
  }
}

// Options built field by field (designated initializers would have to name every member).
TopographyReadOptions with_size(double lx, std::optional<double> ly = std::nullopt) {
  TopographyReadOptions options;
  options.lx = lx;
  options.ly = ly;
  return options;
}
TopographyReadOptions with_channel(const std::string& channel) {
  TopographyReadOptions options;
  options.channel = channel;
  return options;
}
TopographyReadOptions with_fill(FillMethod fill) {
  TopographyReadOptions options;
  options.fill = fill;
  return options;
}
TopographyReadOptions with_level(Levelling level) {
  TopographyReadOptions options;
  options.level = level;
  return options;
}

class FormatFiles : public testing::FolderTest {
 protected:
  FormatFiles() : FolderTest("contactbench_test_formats_") {}

  // A zip archive with the given members, stored uncompressed.
  fs::path write_zip(const std::string& name,
                     const std::vector<std::pair<std::string, std::string>>& members) const {
    const fs::path path = folder_ / name;
    int code = 0;
    zip_t* archive = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &code);
    EXPECT_NE(archive, nullptr);
    for (const auto& [member, content] : members) {
      zip_source_t* source = zip_source_buffer(archive, content.data(), content.size(), 0);
      EXPECT_GE(zip_file_add(archive, member.c_str(), source, ZIP_FL_OVERWRITE), 0);
    }
    EXPECT_EQ(zip_close(archive), 0);
    return path;
  }
};

// The members of an archive, for building corrupt variants of a good one.
std::vector<std::pair<std::string, std::string>> zip_members(const fs::path& path) {
  int code = 0;
  zip_t* archive = zip_open(path.c_str(), ZIP_RDONLY, &code);
  std::vector<std::pair<std::string, std::string>> members;
  for (zip_int64_t k = 0; k < zip_get_num_entries(archive, 0); ++k) {
    zip_stat_t stat;
    zip_stat_index(archive, static_cast<zip_uint64_t>(k), 0, &stat);
    std::string content(stat.size, '\0');
    zip_file_t* file = zip_fopen_index(archive, static_cast<zip_uint64_t>(k), 0);
    zip_fread(file, content.data(), stat.size);
    zip_fclose(file);
    members.emplace_back(stat.name, std::move(content));
  }
  zip_close(archive);
  return members;
}

// ---------------------------------------------------------------------------------------------------------
// Each sample against the reference table.

TEST(FormatSamples, X3pFloat64WithRectangularPixels) {
  const TopographyReading reading = read_topography_reading(kFormatSamples / "x3p-2.x3p");
  EXPECT_EQ(reading.format, TopographyFormat::x3p);
  const Surface& s = reading.surface;
  expect_sample(s, 650, 650, 8.297673139e-05, 2.044783738e-04, 7.728033274e-08);
  // Orientation: dx and dy differ, and these three heights pin which axis is which.
  expect_relative(s.heights()(0, 0), 6.579781341e-08, "h(x0, y0)");
  expect_relative(s.heights()(0, 1), 7.419121341e-08, "h(x1, y0)");
  expect_relative(s.heights()(1, 0), 6.233641341e-08, "h(x0, y1)");
  expect_relative(s.mean_height(), -2.491824169e-09, "mean");
}

TEST(FormatSamples, MetroProNonSquareWithOrientationFromTheRawBytes) {
  const fs::path file = kFormatSamples / "metropro-1.dat";
  const Surface s = read_topography(file);
  expect_sample(s, 640, 480, 7.028812979e-04, 5.271609734e-04, 7.528822205e-08);
  expect_relative(s.heights()(0, 0), 5.057531456e-05, "h(x0, y0)");
  // Phase data start at byte 615234 as big-endian int32 with x fastest: counts at (x1, y0) and (x0, y1) taken
  // straight from the file, scaled by h(x0, y0) / its counts (5814919), must be where the reader put them.
  const std::string bytes = read_bytes(file);
  const auto counts_at = [&](std::size_t index) {
    return formats::BinaryView::decode<std::int32_t>(bytes.data() + 615234 + 4 * index,
                                                     formats::ByteOrder::big);
  };
  ASSERT_EQ(counts_at(0), 5814919);
  const double per_count = s.heights()(0, 0) / 5814919.0;
  expect_relative(s.heights()(0, 1), counts_at(1) * per_count, "h(x1, y0)");
  expect_relative(s.heights()(1, 0), counts_at(640) * per_count, "h(x0, y1)");
}

TEST(FormatSamples, SdfAsciiNonSquare) {
  const Surface s = read_topography(kFormatSamples / "sdf-1.sdf");
  expect_sample(s, 7, 4, 7.0e-06, 4.0e-06, 1.360289729e-08);
  EXPECT_DOUBLE_EQ(s.heights()(0, 0), 1.0e-6);
  EXPECT_DOUBLE_EQ(s.heights()(0, 5), 0.96858e-6);  // first profile, sixth point
  EXPECT_DOUBLE_EQ(s.heights()(3, 0), 0.97986e-6);  // last profile, first point
}

TEST(FormatSamples, NpyNeedsTheCallersSize) {
  const fs::path file = kFormatSamples / "example-2d.npy";
  expect_refused(file, "no lateral size");
  // The array states no unit and its Sq, 2.7 taken as metres, is implausible: refused unless the unit is
  // said.
  expect_refused(file, "Sq 2.71 m, outside the plausible 1 pm to 1 mm", with_size(2.0));
  TopographyReadOptions options = with_size(2.0);
  options.unit = "m";
  const Surface s = read_topography(file, options);
  EXPECT_EQ(s.heights()(0, 0), 0.1);
  EXPECT_EQ(s.heights()(0, 1), 1.0);
  EXPECT_EQ(s.heights()(1, 0), 4.0);
  EXPECT_EQ(s.heights()(1, 1), 7.0);
  expect_relative(s.rms_height(), 2.711434122, "rms");
}

TEST(FormatSamples, NanoscopeEveryHeightChannelAndCorners) {
  const fs::path file = kFormatSamples / "di-1.di";
  const TopographyReading first = read_topography_reading(file);
  EXPECT_EQ(first.format, TopographyFormat::nanoscope);
  EXPECT_EQ(first.channels, (std::vector<std::string>{"Height", "Height", "Phase", "AmplitudeError"}));
  expect_sample(first.surface, 512, 512, 5e-07, 5e-07, 9.945986801e-09);
  // Corners as SurfaceTopography's test_topography.py asserts them (to 1e-3 nm there): y grows upwards.
  const HeightMap& h = first.surface.heights();
  EXPECT_NEAR(h(0, 0), 6.059980e-9, 1e-15);
  EXPECT_NEAR(h(511, 0), 2.843159e-9, 1e-15);
  EXPECT_NEAR(h(0, 511), -9.740179e-9, 1e-15);
  EXPECT_NEAR(h(511, 511), -30.306375e-9, 1e-15);
  const Surface second = read_topography(file, with_channel("1"));
  expect_relative(second.rms_height(), 1.140132803e-07, "channel 1 rms");
}

TEST(FormatSamples, NanoscopeDefaultIsTheFirstHeightChannelWhateverItsName) {
  const fs::path file = kFormatSamples / "di-3.di";
  const TopographyReading zsensor = read_topography_reading(file);
  EXPECT_EQ(zsensor.channel, "ZSensor");
  expect_sample(zsensor.surface, 256, 256, 1e-05, 1e-05, 2.264253967e-07);
  const Surface height = read_topography(file, with_channel("Height"));
  expect_relative(height.rms_height(), 2.640028528e-07, "Height rms");
}

TEST(FormatSamples, SensofarNonSquare) {
  const Surface s = read_topography(kFormatSamples / "plu-1.plu");
  expect_sample(s, 768, 576, 1.274880066e-03, 9.561600494e-04, 2.834390988e-06);
}

TEST(FormatSamples, DigitalSurfNonMeasuredPointsAreInvalid) {
  const fs::path file = kFormatSamples / "sur-3.sur";
  expect_refused(file, "233009 of 262144 points");
  const formats::RawTopography raw = read_topography_channels(file);
  ASSERT_EQ(raw.channels.size(), 1u);
  expect_relative(valid_rms(raw.channels[0]), 1.113199427e-03, "rms without the zmin - 2 points");
  const Surface s = read_topography(file, with_fill(FillMethod::mean));
  EXPECT_EQ(s.nx(), 512);
  expect_relative(s.grid().lx, 1.513195520e-01, "lx");
  expect_relative(s.grid().ly, 1.513195520e-01, "ly");
}

TEST(FormatSamples, WykoNonSquareWithInvalidPoints) {
  const fs::path file = kFormatSamples / "opd-1.opd";
  expect_refused(file, "116 of 307200 points");
  const formats::RawTopography raw = read_topography_channels(file);
  ASSERT_EQ(raw.channels.size(), 1u);
  EXPECT_EQ(raw.channels[0].name, "Raw");
  expect_relative(valid_rms(raw.channels[0]), 8.356451163e-09, "rms of the valid points");
  const TopographyReading filled = read_topography_reading(file, with_fill(FillMethod::harmonic));
  EXPECT_EQ(filled.invalid_points, 116);
  EXPECT_EQ(filled.surface.nx(), 640);
  EXPECT_EQ(filled.surface.ny(), 480);
  expect_relative(filled.surface.grid().lx, 1.259091403e-04, "lx");
  expect_relative(filled.surface.grid().ly, 9.443185525e-05, "ly");
}

TEST(FormatSamples, NetcdfNonSquare) {
  const Surface s = read_topography(kFormatSamples / "nc-1.nc");
  expect_sample(s, 5, 10, 5e-09, 1e-08, 5.744562647e-09);
  // Heights 9 - 2 j nm along y, the same for every x.
  for (Index y = 0; y < 10; ++y)
    for (Index x = 0; x < 5; ++x)
      EXPECT_NEAR(s.heights()(y, x), (9.0 - 2.0 * static_cast<double>(y)) * 1e-9, 1e-24);
}

// ---------------------------------------------------------------------------------------------------------
// Round trips.

using testing::bits_of;

Surface generated_surface() {
  // Non-square and rectangular pixels, so a transposition cannot go unnoticed.
  const Grid grid{48, 32, 3e-5, 1.5e-5, true};
  SelfAffinePsd psd;
  psd.sigma = 1e-6;
  psd.hurst = 0.8;
  psd.qr = 2 * std::numbers::pi / 1e-5;
  return generate_surface(grid, psd, 7);
}

TEST_F(FormatFiles, X3pRoundTripIsBitForBitAndKeepsTheMoments) {
  const Surface surface = generated_surface().with_periodic(false);
  const fs::path file = folder_ / "generated.x3p";
  write_topography(file, surface);
  const Surface copy = read_topography(file);
  EXPECT_EQ(bits_of(copy.heights()), bits_of(surface.heights()));
  // The sizes pass through the increment lx / nx and back: one rounding each way.
  EXPECT_NEAR(copy.grid().lx, surface.grid().lx, 4e-16 * surface.grid().lx);
  EXPECT_NEAR(copy.grid().ly, surface.grid().ly, 4e-16 * surface.grid().ly);
  const SpectralMoments before = spectral_moments(surface);
  const SpectralMoments after = spectral_moments(copy);
  // Same heights, sizes within 1e-15: the moments agree to round-off (tolerance::fft_round_off).
  EXPECT_NEAR(after.m0, before.m0, tolerance::fft_round_off * before.m0);
  EXPECT_NEAR(after.m2x, before.m2x, tolerance::fft_round_off * before.m2x);
  EXPECT_NEAR(after.m2y, before.m2y, tolerance::fft_round_off * before.m2y);
  EXPECT_NEAR(after.m4x, before.m4x, tolerance::fft_round_off * before.m4x);
}

TEST_F(FormatFiles, NpyRoundTripIsBitForBit) {
  const Surface surface = generated_surface();
  const fs::path file = folder_ / "generated.npy";
  write_topography(file, surface);
  EXPECT_EQ(detect_topography_format(file), TopographyFormat::npy);
  const Surface copy = read_topography(file, with_size(surface.grid().lx, surface.grid().ly));
  EXPECT_EQ(copy.nx(), 48);
  EXPECT_EQ(bits_of(copy.heights()), bits_of(surface.heights()));
}

// A .npy file written by hand: header dict padded to 64 bytes, then the data.
std::string npy_file(const std::string& descr, bool fortran, Index rows, Index columns,
                     const std::string& data) {
  std::string header = "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") +
                       ", 'shape': (" + std::to_string(rows) + ", " + std::to_string(columns) + "), }";
  header.append((64 - (10 + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string file = "\x93NUMPY\x01";
  file += '\0';
  file += static_cast<char>(header.size());
  file += '\0';
  return file + header + data;
}

template <typename T>
std::string encoded(const std::vector<T>& values, bool big_endian) {
  std::string data;
  for (const T value : values) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if (big_endian) std::reverse(bytes, bytes + sizeof(T));
    data.append(bytes, sizeof(T));
  }
  return data;
}

TEST_F(FormatFiles, NpyReadsBothByteOrdersBothMemoryOrdersAndFloat32) {
  // The array [[1, 2, 3], [4, 5, 6]]: 2 rows (y) by 3 columns (x).
  const std::vector<double> c_order = {1, 2, 3, 4, 5, 6};
  const std::vector<double> fortran_order = {1, 4, 2, 5, 3, 6};
  const std::vector<float> c_order_float = {1, 2, 3, 4, 5, 6};
  const std::vector<fs::path> files = {
      write("le_c.npy", npy_file("<f8", false, 2, 3, encoded(c_order, false))),
      write("be_c.npy", npy_file(">f8", false, 2, 3, encoded(c_order, true))),
      write("le_f.npy", npy_file("<f8", true, 2, 3, encoded(fortran_order, false))),
      write("be_f.npy", npy_file(">f8", true, 2, 3, encoded(fortran_order, true))),
      write("f4_le.npy", npy_file("<f4", false, 2, 3, encoded(c_order_float, false))),
      write("f4_be.npy", npy_file(">f4", false, 2, 3, encoded(c_order_float, true))),
  };
  for (const fs::path& file : files) {
    TopographyReadOptions options = with_size(3.0);
    options.unit = "m";  // Sq 1.7 needs the unit said
    const Surface s = read_topography(file, options);
    ASSERT_EQ(s.nx(), 3) << file;
    ASSERT_EQ(s.ny(), 2) << file;
    for (Index y = 0; y < 2; ++y)
      for (Index x = 0; x < 3; ++x)
        EXPECT_EQ(s.heights()(y, x), static_cast<double>(1 + x + 3 * y)) << file;
  }
}

// An x3p archive built by hand around main.xml text, for the data types and the mask.
std::string x3p_main_xml(const std::string& type, Index nx, Index ny, const std::string& z_extra,
                         const std::string& data_link_extra) {
  return "<?xml version=\"1.0\"?>\n<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\"><Record1>"
         "<Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>"
         "<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6</Increment><Offset>0</Offset></CX>"
         "<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2e-6</Increment><Offset>0</Offset></CY>"
         "<CZ><AxisType>A</AxisType><DataType>" +
         type + "</DataType>" + z_extra + "</CZ></Axes></Record1><Record3><MatrixDimension><SizeX>" +
         std::to_string(nx) + "</SizeX><SizeY>" + std::to_string(ny) +
         "</SizeY><SizeZ>1</SizeZ></MatrixDimension><DataLink>" +
         "<PointDataLink>bindata/data.bin</PointDataLink>" + data_link_extra +
         "</DataLink></Record3></p:ISO5436_2>\n";
}

TEST_F(FormatFiles, X3pEveryDataTypeWithIncrementOffsetAndValidMask) {
  // 3 x 2 points with raw values 1..6; z = 1e-9 * raw + 1e-6; the mask marks the fifth point invalid.
  const std::string increment = "<Increment>1e-9</Increment><Offset>1e-6</Offset>";
  const std::string mask(1, static_cast<char>(0b101111));
  const std::vector<std::pair<std::string, std::string>> types = {
      {"I", encoded(std::vector<std::int16_t>{1, 2, 3, 4, 5, 6}, false)},
      {"L", encoded(std::vector<std::int32_t>{1, 2, 3, 4, 5, 6}, false)},
      {"F", encoded(std::vector<float>{1, 2, 3, 4, 5, 6}, false)},
      {"D", encoded(std::vector<double>{1, 2, 3, 4, 5, 6}, false)},
  };
  for (const auto& [type, data] : types) {
    const std::string xml = x3p_main_xml(type, 3, 2, increment,
                                         "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
                                         "<MD5ChecksumPointData>" +
                                             formats::md5_hex(data) + "</MD5ChecksumPointData>");
    const fs::path file =
        write_zip("type_" + type + ".x3p",
                  {{"main.xml", xml}, {"bindata/data.bin", data}, {"bindata/valid.bin", mask}});
    const formats::RawTopography raw = read_topography_channels(file);
    const formats::Channel& channel = raw.channels.at(0);
    ASSERT_EQ(channel.nx, 3) << type;
    ASSERT_EQ(channel.ny, 2) << type;
    EXPECT_DOUBLE_EQ(*channel.lx, 3e-6) << type;
    EXPECT_DOUBLE_EQ(*channel.ly, 4e-6) << type;
    for (std::size_t k = 0; k < 6; ++k) {
      if (k == 4) {
        EXPECT_TRUE(std::isnan(channel.values[k])) << type;
      } else {
        EXPECT_DOUBLE_EQ(channel.values[k], 1e-9 * static_cast<double>(k + 1) + 1e-6)
            << type << " point " << k;
      }
    }
    expect_refused(file, "1 of 6 points");
    const Surface filled = read_topography(file, with_fill(FillMethod::mean));
    EXPECT_DOUBLE_EQ(filled.heights()(1, 1), 1e-6 + 1e-9 * (1 + 2 + 3 + 4 + 6) / 5.0) << type;
  }
}

TEST_F(FormatFiles, X3pZeroOrNonFiniteZIncrementIsRefusedNamingTheField) {
  // A zero increment made every height 0 (a flat surface, exit 0); NaN or Inf would make them all invalid.
  const std::string data = encoded(std::vector<std::int32_t>{1, 2, 3, 4, 5, 6}, false);
  for (const std::string increment : {"0", "0.0", "NaN", "inf", "-INF"}) {
    const std::string xml = x3p_main_xml("L", 3, 2, "<Increment>" + increment + "</Increment>", "");
    const fs::path file = write_zip("zero.x3p", {{"main.xml", xml}, {"bindata/data.bin", data}});
    const std::string before = formats::md5_hex(read_bytes(file));
    expect_refused(file, "<Record1/Axes/CZ/Increment>", {});
    EXPECT_EQ(formats::md5_hex(read_bytes(file)), before) << increment;
  }
}

TEST_F(FormatFiles, X3pDeclaringMoreThanMemoryIsRefusedBeforeInflating) {
  // 65535 x 65535 float64 points: 32 GiB of data plus 32 B a point of reading (about 160 GiB), far beyond
  // any test machine; the estimate refuses at once, with generate's message, before the member is touched.
  const std::string xml = x3p_main_xml("D", 65535, 65535, "", "");
  const fs::path file =
      write_zip("huge.x3p", {{"main.xml", xml}, {"bindata/data.bin", std::string(64, '\0')}});
  expect_refused(file, "reading x3p data of type D of 65535 x 65535 points needs about 160.0 GiB of memory");
}

TEST_F(FormatFiles, NpyInfIsAnInvalidPointAsNan) {
  // docs/formats.md "invalid points": NaN and Inf alike, in every format.
  const double inf = std::numeric_limits<double>::infinity();
  const fs::path file = write(
      "inf.npy", npy_file("<f8", false, 2, 3, encoded(std::vector<double>{1, 2, -inf, 4, inf, 6}, false)));
  TopographyReadOptions options = with_size(3.0);
  options.unit = "m";
  expect_refused(file, "2 of 6 points of channel 'array' are invalid", options);
  options.fill = FillMethod::mean;
  const Surface filled = read_topography(file, options);
  // The mean of 1, 2, 4, 6: exact in binary.
  EXPECT_EQ(filled.heights()(0, 2), 3.25);
  EXPECT_EQ(filled.heights()(1, 1), 3.25);
}

TEST_F(FormatFiles, SdfBinaryWithInt16AndTheMissingPointValue) {
  // No binary sample exists: this one follows ISO 25178-71's packed header (81 bytes, little-endian).
  std::string header = "bISO-1.0";
  header += std::string("TEST      ", 10) + std::string(12, '0') + std::string(12, '0');
  header += encoded(std::vector<std::uint16_t>{3, 2}, false);  // NumPoints (nx), NumProfiles (ny)
  header +=
      encoded(std::vector<double>{1e-6, 2e-6, 1e-9, 1e-9}, false);  // Xscale, Yscale, Zscale, Zresolution
  header += std::string{'\0', '\5', '\0'};  // Compression, DataType 5 (int16), CheckType
  ASSERT_EQ(header.size(), 81u);
  const std::string data = encoded(std::vector<std::int16_t>{1, 2, 3, 4, -32768, 6}, false);
  const fs::path file = write("binary.sdf", header + data);
  const formats::Channel channel = read_topography_channels(file).channels.at(0);
  ASSERT_EQ(channel.nx, 3);
  ASSERT_EQ(channel.ny, 2);
  EXPECT_DOUBLE_EQ(*channel.lx, 3e-6);
  EXPECT_DOUBLE_EQ(*channel.ly, 4e-6);
  EXPECT_DOUBLE_EQ(channel.values[5], 6e-9);
  EXPECT_TRUE(std::isnan(channel.values[4]));
  expect_refused(file, "1 of 6 points");
  expect_refused(write("short.sdf", header + data.substr(0, 10)), "truncated or corrupt: SDF binary data");
}

TEST_F(FormatFiles, NanoscopeFourByteDataCarrySixteenMoreBitsOfResolution) {
  // No 4-byte sample exists: a minimal header by hand, 2 x 2 int32 counts, 2 V hard scale, 10 nm/V.
  const std::string header_text =
      "\\*File list\r\n\\Data length: 2048\r\n\\*Scanner list\r\n\\@Sens. Zsens: V 10.0 nm/V\r\n"
      "\\*Ciao image list\r\n\\Data offset: 2048\r\n\\Data length: 16\r\n\\Bytes/pixel: 4\r\n"
      "\\Samps/line: 2\r\n\\Number of lines: 2\r\n\\Scan Size: 1 1 ~m\r\n"
      "\\@2:Image Data: S [Height] \"Height\"\r\n\\@2:Z scale: V [Sens. Zsens] (0.0001 V/LSB) 2.0 V\r\n"
      "\\*File list end\r\n";
  std::string bytes = header_text + std::string(2048 - header_text.size(), '\0');
  bytes += encoded(std::vector<std::int32_t>{65536, 131072, -65536, 0}, false);
  const Surface s = read_topography(write("four.di", bytes));
  // count * (2 V / 65536) * 10 nm/V / 65536: a count of 65536 is 2 * 10 / 65536 nm.
  const double unit = 2.0 * 10.0 / 65536.0 * 1e-9;
  EXPECT_DOUBLE_EQ(s.grid().lx, 1e-6);
  // The first stored line is the top (y = 1).
  EXPECT_DOUBLE_EQ(s.heights()(1, 0), unit);
  EXPECT_DOUBLE_EQ(s.heights()(1, 1), 2 * unit);
  EXPECT_DOUBLE_EQ(s.heights()(0, 0), -unit);
  EXPECT_DOUBLE_EQ(s.heights()(0, 1), 0.0);
}

TEST_F(FormatFiles, DetectionIsByContentNotByExtension) {
  const std::vector<std::pair<std::string, TopographyFormat>> cases = {
      {"x3p-2.x3p", TopographyFormat::x3p},          {"metropro-1.dat", TopographyFormat::metropro},
      {"sdf-1.sdf", TopographyFormat::sdf},          {"example-2d.npy", TopographyFormat::npy},
      {"di-3.di", TopographyFormat::nanoscope},      {"plu-1.plu", TopographyFormat::sensofar},
      {"sur-3.sur", TopographyFormat::digital_surf}, {"opd-1.opd", TopographyFormat::wyko},
      {"nc-1.nc", TopographyFormat::netcdf},
  };
  for (const auto& [name, format] : cases) {
    const fs::path renamed = write("renamed_" + name + ".bin", read_bytes(kFormatSamples / name));
    EXPECT_EQ(detect_topography_format(renamed), format) << name;
  }
  // A Sensofar file named like a MetroPro file is still read as what it is.
  const fs::path plu_as_dat = write("plu.dat", read_bytes(kFormatSamples / "plu-1.plu"));
  EXPECT_EQ(read_topography(plu_as_dat).nx(), 768);
}

// ---------------------------------------------------------------------------------------------------------
// Bad files: each refused with the file's name and what is wrong.

TEST_F(FormatFiles, TruncatedFilesAreRefused) {
  expect_refused(kFormatSamples / "di_corrupted.di", "truncated or corrupt");
  const std::string metropro = read_bytes(kFormatSamples / "metropro-1.dat");
  expect_refused(write("cut.dat", metropro.substr(0, metropro.size() / 2)), "truncated or corrupt");
  expect_refused(write("header_only.dat", metropro.substr(0, 100)), "truncated or corrupt");
  const std::string x3p = read_bytes(kFormatSamples / "x3p-2.x3p");
  expect_refused(write("cut.x3p", x3p.substr(0, x3p.size() - 100)), "zip");
  const std::string plu = read_bytes(kFormatSamples / "plu-1.plu");
  expect_refused(write("cut.plu", plu.substr(0, 1000)), "truncated or corrupt");
  const std::string sur = read_bytes(kFormatSamples / "sur-3.sur");
  expect_refused(write("cut.sur", sur.substr(0, sur.size() - 1)), "truncated or corrupt");
  const std::string opd = read_bytes(kFormatSamples / "opd-1.opd");
  expect_refused(write("cut.opd", opd.substr(0, opd.size() / 3)), "truncated or corrupt");
  expect_refused(write("cut.sdf", "aISO-1.0\nNumPoints = 3\n"), "truncated SDF");
}

TEST_F(FormatFiles, WrongMagicIsRefused) {
  expect_refused(kFormatSamples / "wrongnpyfile.npy", "wrong magic");
  const std::string sdf = read_bytes(kFormatSamples / "sdf-1.sdf");
  expect_refused(write("text.x3p", sdf.substr(8)), "wrong magic");
  expect_refused(write("text.sur", "DIGITAL SORF and more"), "wrong magic");
  expect_refused(write("text.opd", "no directory here at all"), "wrong magic");
  expect_refused(write("text.nc", "CDX\x01"), "wrong magic");
  expect_refused(write("hdf5.nc", std::string("\x89HDF\r\n\x1a\n", 8) + std::string(64, '\0')),
                 "NetCDF-4 (HDF5)");
  expect_refused(write("text.dat", "\x88\x1b\x03\x10 not metropro"), "wrong magic");
}

TEST_F(FormatFiles, HeaderPromisingMoreDataThanPresentIsRefused) {
  expect_refused(
      write("short.npy", npy_file("<f8", false, 20, 20, encoded(std::vector<double>{1, 2, 3, 4}, false))),
      "truncated or corrupt: .npy data (20 x 20)");
  const std::string sdf = read_bytes(kFormatSamples / "sdf-1.sdf");
  std::string more = sdf;
  more.replace(more.find("NumProfiles = 4"), 15, "NumProfiles = 5");
  expect_refused(write("more.sdf", more), "promises 7 x 5 = 35 values but the data hold 28");
  std::string metropro = read_bytes(kFormatSamples / "metropro-1.dat");
  metropro[70] = static_cast<char>(0x03);  // cn_org_height 480 -> 0x03e0 = 992 lines
  expect_refused(write("more.dat", metropro), "truncated or corrupt: MetroPro phase data");
  // A zip member shorter than the matrix it should fill.
  const std::string xml = x3p_main_xml("D", 10, 10, "", "");
  expect_refused(write_zip("short.x3p", {{"main.xml", xml}, {"bindata/data.bin", std::string(80, '\0')}}),
                 "holds 80 bytes but 10 x 10 points of type D need 800");
}

TEST_F(FormatFiles, UnknownDataTypesAreRefused) {
  const std::string xml = x3p_main_xml("Q", 2, 2, "", "");
  expect_refused(write_zip("q.x3p", {{"main.xml", xml}, {"bindata/data.bin", std::string(64, '\0')}}),
                 "unknown x3p data type 'Q'");
  std::string sdf = read_bytes(kFormatSamples / "sdf-1.sdf");
  sdf.replace(sdf.find("DataType = 7"), 12, "DataType = 9");
  expect_refused(write("type9.sdf", sdf), "unknown SDF DataType 9");
  expect_refused(write("complex.npy", npy_file("<c16", false, 1, 1, std::string(16, '\0'))),
                 "unsupported .npy data type '<c16'");
  std::string di = read_bytes(kFormatSamples / "di-3.di");
  const std::size_t pixel = di.find("Bytes/pixel: 2");
  di[pixel + 13] = '3';
  expect_refused(write("three.di", di), "3 bytes per pixel; known: 2 and 4");
}

TEST_F(FormatFiles, ZipWithoutMainXmlIsRefused) {
  expect_refused(write_zip("nomain.x3p", {{"bindata/data.bin", std::string(64, '\0')}}), "has no main.xml");
}

TEST_F(FormatFiles, FailingChecksumsAreRefused) {
  std::vector<std::pair<std::string, std::string>> members = zip_members(kFormatSamples / "x3p-2.x3p");
  for (auto& [name, content] : members)
    if (name == "bindata/data.bin") content[1000] = static_cast<char>(content[1000] ^ 0x01);
  expect_refused(write_zip("data.x3p", members), "checksum failure: main.xml gives MD5 33ee4e6b");
  members = zip_members(kFormatSamples / "x3p-2.x3p");
  for (auto& [name, content] : members)
    if (name == "main.xml") content.replace(content.find("Mountains"), 9, "Mountainz");
  expect_refused(write_zip("xml.x3p", members), "checksum failure: md5checksum.hex");
}

// Every sample cut short at many lengths and with bytes flipped in its first kilobyte: reading either
// succeeds or throws InputError; nothing else (no crash, no other exception, no hang).
TEST_F(FormatFiles, MutatedSamplesNeverCrash) {
  std::mt19937_64 random(13);
  for (const auto& entry : fs::directory_iterator(kFormatSamples)) {
    if (entry.path().extension() == ".md") continue;
    const std::string bytes = read_bytes(entry.path());
    const std::string extension = entry.path().extension().string();
    std::vector<std::string> variants;
    for (const std::size_t cut : {std::size_t{0}, std::size_t{1}, std::size_t{9}, std::size_t{100},
                                  std::size_t{511}, bytes.size() / 2, bytes.size() - 1})
      variants.push_back(bytes.substr(0, std::min(cut, bytes.size())));
    for (int flip = 0; flip < 12; ++flip) {
      std::string mutated = bytes;
      for (int k = 0; k < 4; ++k) {
        const std::size_t at = random() % std::min<std::size_t>(1024, mutated.size());
        mutated[at] = static_cast<char>(random() & 0xff);
      }
      variants.push_back(std::move(mutated));
    }
    for (std::size_t k = 0; k < variants.size(); ++k) {
      const fs::path file = write("variant" + std::to_string(k) + extension, variants[k]);
      try {
        TopographyReadOptions options = with_fill(FillMethod::mean);
        options.lx = 1e-6;
        (void)read_topography(file, options);
      } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos);
      } catch (const std::exception& error) {
        ADD_FAILURE() << entry.path().filename() << " variant " << k
                      << ": not an InputError: " << error.what();
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------------
// Channels, invalid points, levelling.

TEST(FormatChannels, UnknownOrNonHeightChannelIsAnErrorListingTheChannels) {
  const fs::path file = kFormatSamples / "di-1.di";
  expect_refused(
      file,
      "unknown channel 'Topography'; the file's channels: 0 'Height', 1 'Height', 2 'Phase' (not a "
      "height), 3 'AmplitudeError' (not a height)",
      with_channel("Topography"));
  expect_refused(file, "unknown channel '7'", with_channel("7"));
  expect_refused(file, "channel 'Phase' does not hold heights", with_channel("Phase"));
  expect_refused(kFormatSamples / "sdf-1.sdf", "unknown channel 'Height'", with_channel("Height"));
}

TEST(FormatInvalidPoints, HarmonicFillHasNoNaNAndObeysTheMaximumPrinciple) {
  const fs::path file = kFormatSamples / "opd-1.opd";
  const formats::Channel raw = read_topography_channels(file).channels.at(0);
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (const double v : raw.values)
    if (!std::isnan(v)) {
      low = std::min(low, v);
      high = std::max(high, v);
    }
  for (const FillMethod method : {FillMethod::harmonic, FillMethod::mean}) {
    const Surface s = read_topography(file, with_fill(method));
    EXPECT_TRUE(s.heights().isFinite().all());
    // Valid points unchanged; filled ones inside the valid range (a discrete harmonic function takes its
    // extremes on the boundary, and a mean lies between the extremes).
    for (Index k = 0; k < s.grid().points(); ++k) {
      const double value = s.heights()(k / s.nx(), k % s.nx());
      if (std::isnan(raw.values[static_cast<std::size_t>(k)])) {
        EXPECT_GE(value, low);
        EXPECT_LE(value, high);
      } else {
        EXPECT_EQ(value, raw.values[static_cast<std::size_t>(k)]);
      }
    }
  }
}

TEST(FormatInvalidPoints, HarmonicFillOfALinearFieldIsExact) {
  // A linear field is harmonic: holes punched in its interior are filled back with the same values (to
  // round-off). At the grid's edge a point has three neighbours and the discrete equation is no longer exact
  // for a linear field, so the holes stay inside.
  std::vector<double> values(20 * 10);
  for (Index y = 0; y < 10; ++y)
    for (Index x = 0; x < 20; ++x)
      values[static_cast<std::size_t>(y * 20 + x)] =
          2.0 * static_cast<double>(x) - 3.0 * static_cast<double>(y);
  std::vector<double> holed = values;
  for (const std::size_t k : {21u, 22u, 41u, 42u, 43u, 98u, 150u})
    holed[k] = std::numeric_limits<double>::quiet_NaN();
  fill_invalid_points(holed, 20, 10, FillMethod::harmonic);
  for (std::size_t k = 0; k < values.size(); ++k)
    EXPECT_NEAR(holed[k], values[k], 1e-12) << k;  // a sparse direct solve of a small system: round-off
  std::vector<double> none(4, std::numeric_limits<double>::quiet_NaN());
  EXPECT_THROW(fill_invalid_points(none, 2, 2, FillMethod::harmonic), Error);
}

TEST(FormatLevelling, PlaneRemovesATiltAndMeanRemovesTheMean) {
  const Surface sdf = read_topography(kFormatSamples / "sdf-1.sdf");
  const TopographyReading none = read_topography_reading(kFormatSamples / "sdf-1.sdf");
  EXPECT_EQ(none.level, Levelling::none);
  EXPECT_EQ(bits_of(none.surface.heights()), bits_of(sdf.heights()));
  const Surface mean = read_topography(kFormatSamples / "sdf-1.sdf", with_level(Levelling::mean));
  EXPECT_NEAR(mean.mean_height(), 0, 1e-21);  // round-off of the mean of 28 values of 1e-6
  // A tilted plane plus a bump: plane levelling removes the plane exactly and leaves the bump's own plane
  // component, which is zero for a bump symmetric about the centre.
  HeightMap heights(9, 11);
  for (Index y = 0; y < 9; ++y)
    for (Index x = 0; x < 11; ++x)
      heights(y, x) = 1e-6 + 2e-8 * static_cast<double>(x) - 5e-9 * static_cast<double>(y) +
                      (x == 5 && y == 4 ? 1e-7 : 0.0);
  const Grid grid{11, 9, 11e-6, 9e-6, false};
  level_heights(heights, grid, Levelling::plane);
  for (Index y = 0; y < 9; ++y)
    for (Index x = 0; x < 11; ++x)
      EXPECT_NEAR(heights(y, x), (x == 5 && y == 4 ? 1e-7 : 0.0) - 1e-7 / 99.0, 1e-20) << x << "," << y;
}

}  // namespace
}  // namespace contactbench
