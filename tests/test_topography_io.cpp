// Reading and writing topography files: the measured instrument exports, the project's lossless format,
// plain matrices, and one test per kind of bad input.
#include "contactbench/core/topography_io.hpp"

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "contactbench/core/error.hpp"
#include "height_bits.hpp"
#include "test_folder.hpp"
#include "tolerances.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

// The measured files and their Sq values come from SurfaceTopography's test data
// (ContactEngineering/SurfaceTopography, test/file_format_examples, commit
// 119cb66ade8917a0a62a878c82d459f959566760, MIT licence); see data/measured/README.md.
const fs::path measured_folder{CB_DATA_DIR "/measured"};

// The one rounding of a unit conversion (10.00 times 1e-6, say) against a decimal literal: a few ulp.
constexpr double unit_conversion_rounding = 1e-15;

// Sq as SurfaceTopography asserts it, compared relatively.
void expect_sq(const Surface& surface, double reference) {
  // tolerance::measured_sq: both sides sum the same decimal data in double, only the order differs.
  EXPECT_NEAR(surface.rms_height(), reference, tolerance::measured_sq * reference);
}

// The non-blank lines of a text file, for checking the reader against the file's own numbers.
std::vector<std::string> lines_of(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

// Reading must fail with an InputError naming the file, the line (0: the file as a whole) and the reason.
void expect_input_error(const fs::path& file, long line, std::string_view reason,
                        const TopographyReadOptions& options = {}) {
  try {
    read_topography(file, options);
    ADD_FAILURE() << file << ": read without error, expected one at line " << line;
  } catch (const InputError& error) {
    const std::string message = error.what();
    const std::string location =
        file.string() + (line > 0 ? ":" + std::to_string(line) + ": " : std::string(": "));
    EXPECT_TRUE(message.starts_with(location)) << "expected '" << location << "' in: " << message;
    EXPECT_EQ(error.line(), line) << message;
    EXPECT_NE(message.find(reason), std::string::npos) << "expected '" << reason << "' in: " << message;
  }
}

// Each test writes its files into a fresh folder of its own and removes it afterwards.
class TopographyIoFiles : public testing::FolderTest {
 protected:
  TopographyIoFiles() : FolderTest("contactbench_test_topography_io_") {}
};

using testing::bits_of;

TEST(TopographyIoMeasured, InterferometerSquareMatrix2) {
  const Surface surface = read_topography(measured_folder / "matrix-2.txt");
  EXPECT_EQ(surface.nx(), 650);
  EXPECT_EQ(surface.ny(), 650);
  // Exact: the reader forms the same product of the same two doubles (w or h times the pixel size).
  EXPECT_EQ(surface.grid().lx, 650 * 3.69862e-7);
  EXPECT_EQ(surface.grid().ly, 650 * 3.69862e-7);
  EXPECT_FALSE(surface.grid().periodic);
  expect_sq(surface, 2.7722350402740072e-07);
}

TEST(TopographyIoMeasured, GwyddionMatrix3) {
  const Surface surface = read_topography(measured_folder / "matrix-3.txt");
  EXPECT_EQ(surface.nx(), 256);
  EXPECT_EQ(surface.ny(), 256);
  EXPECT_NEAR(surface.grid().lx, 10e-6, unit_conversion_rounding * 10e-6);  // 10.00 um: one rounding
  EXPECT_NEAR(surface.grid().ly, 10e-6, unit_conversion_rounding * 10e-6);
  EXPECT_FALSE(surface.grid().periodic);
  expect_sq(surface, 3.5222918750198742e-08);
}

TEST(TopographyIoMeasured, InterferometerNonSquareMatrix4) {
  const fs::path file = measured_folder / "matrix-4.txt";
  const Surface surface = read_topography(file);
  EXPECT_EQ(surface.nx(), 75);   // w: columns along x
  EXPECT_EQ(surface.ny(), 305);  // h: rows along y
  // Exact: the same product of the same doubles as in the reader.
  EXPECT_EQ(surface.grid().lx, 75 * 3.69862e-7);
  EXPECT_EQ(surface.grid().ly, 305 * 3.69862e-7);
  EXPECT_FALSE(surface.grid().periodic);
  expect_sq(surface, 1.1745891510991089e-07);

  // Orientation: heights(row = y, column = x) holds the file's row y, number x, times the factor.
  const std::vector<std::string> lines = lines_of(file);
  ASSERT_GE(lines.size(), 6u);
  ASSERT_TRUE(lines[3].starts_with("height conversion factor (-> m)="));
  const double factor = std::stod(lines[3].substr(lines[3].find('=') + 1));
  std::istringstream first_row(lines[4]);
  std::istringstream second_row(lines[5]);
  double first_row_x0 = 0, first_row_x1 = 0, second_row_x0 = 0;
  first_row >> first_row_x0 >> first_row_x1;
  second_row >> second_row_x0;
  // Exact: both parsers round the same decimal correctly, and the reader multiplies by the same factor.
  EXPECT_EQ(surface.heights()(0, 0), first_row_x0 * factor);
  EXPECT_EQ(surface.heights()(0, 1), first_row_x1 * factor);
  EXPECT_EQ(surface.heights()(1, 0), second_row_x0 * factor);
}

TEST(TopographyIoMeasured, DetectsTheInstrumentFormats) {
  EXPECT_EQ(detect_topography_format(measured_folder / "matrix-2.txt"), TopographyFormat::interferometer);
  EXPECT_EQ(detect_topography_format(measured_folder / "matrix-3.txt"), TopographyFormat::gwyddion);
  EXPECT_EQ(detect_topography_format(measured_folder / "matrix-4.txt"), TopographyFormat::interferometer);
  EXPECT_EQ(to_string(TopographyFormat::gwyddion), "gwyddion");
}

TEST_F(TopographyIoFiles, RoundTripIsBitForBit) {
  HeightMap heights(3, 4);  // ny = 3 rows, nx = 4 columns: a transposition would show
  constexpr Real tiny = std::numeric_limits<Real>::denorm_min();
  constexpr Real huge = std::numeric_limits<Real>::max();
  heights << 0.1, 1e-300, -3.14159e-7, std::nextafter(1.0, 2.0),  // row y = 0
      tiny, -0.0, 1.0 / 3.0, huge,                                // row y = 1
      -huge, std::numeric_limits<Real>::min(), std::nextafter(0.1, 0.0), 6.02214076e23;
  const Surface original(Grid{4, 3, 1e-3 / 3.0, std::nextafter(2.5e-4, 1.0), true}, heights);
  const fs::path file = folder_ / "surface.txt";
  write_surface(file, original);

  EXPECT_EQ(detect_topography_format(file), TopographyFormat::project);
  const Surface copy = read_topography(file);
  EXPECT_EQ(copy.nx(), 4);
  EXPECT_EQ(copy.ny(), 3);
  // Exact (==, and bit patterns for the heights): the writer prints the shortest round-trip decimal.
  EXPECT_EQ(copy.grid().lx, original.grid().lx);
  EXPECT_EQ(copy.grid().ly, original.grid().ly);
  EXPECT_TRUE(copy.grid().periodic);
  EXPECT_EQ(bits_of(copy.heights()), bits_of(original.heights()));

  // The temporary file was renamed, not left beside the result.
  EXPECT_EQ(std::distance(fs::directory_iterator(folder_), fs::directory_iterator()), 1);
}

TEST_F(TopographyIoFiles, ProjectFormatKeepsThePeriodicFlagUnlessOverridden) {
  HeightMap heights(2, 3);
  heights << 1e-9, -2e-9, 3e-9, 4e-9, 5e-9, -6e-9;
  const fs::path file = folder_ / "surface.txt";
  write_surface(file, Surface(Grid{3, 2, 3e-6, 2e-6, false}, heights));
  EXPECT_FALSE(read_topography(file).grid().periodic);
  TopographyReadOptions options;
  options.periodic = true;
  EXPECT_TRUE(read_topography(file, options).grid().periodic);
  // Sizes the caller gives that agree with the file's are accepted.
  options.lx = 3e-6;
  options.ly = 2e-6 * (1 + 1e-8);
  EXPECT_NO_THROW(read_topography(file, options));
}

TEST_F(TopographyIoFiles, PlainMatrixUsesTheGivenSizes) {
  const fs::path file = write("plain.txt", "1e-9 2e-9 3e-9\n4e-9 5e-9 6e-9\n");
  EXPECT_EQ(detect_topography_format(file), TopographyFormat::plain_matrix);
  TopographyReadOptions options;
  options.lx = 3e-6;
  options.ly = 5e-6;
  const Surface surface = read_topography(file, options);
  EXPECT_EQ(surface.nx(), 3);
  EXPECT_EQ(surface.ny(), 2);
  // Exact: the caller's sizes and the file's heights are passed through untouched.
  EXPECT_EQ(surface.grid().lx, 3e-6);
  EXPECT_EQ(surface.grid().ly, 5e-6);
  EXPECT_EQ(surface.heights()(0, 2), 3e-9);
  EXPECT_EQ(surface.heights()(1, 0), 4e-9);
  EXPECT_FALSE(surface.grid().periodic);
  options.periodic = true;
  EXPECT_TRUE(read_topography(file, options).grid().periodic);
}

TEST_F(TopographyIoFiles, PlainMatrixDefaultsToSquarePixels) {
  const fs::path file = write("plain.txt", "1 2 3 4\n5 6 7 8\n");
  TopographyReadOptions options;
  options.lx = 4e-6;
  options.unit = "m";  // Sq 2.3 m needs the unit said (docs/formats.md "units")
  const Surface surface = read_topography(file, options);
  // ly = lx * ny / nx = 2e-6: one multiplication and one division, a few ulp.
  EXPECT_NEAR(surface.grid().ly, 2e-6, unit_conversion_rounding * 2e-6);
  EXPECT_NEAR(surface.grid().dx(), surface.grid().dy(), unit_conversion_rounding * surface.grid().dx());
}

TEST_F(TopographyIoFiles, AcceptsCrlfTabsBlankLinesAndScientificNotation) {
  const fs::path file = write("plain.txt", "\r\n  3.69862e-007\t+2.5E+00 \r\n\r\n\t-1 0.5\r\n");
  TopographyReadOptions options;
  options.lx = 1e-6;
  options.unit = "m";
  const Surface surface = read_topography(file, options);
  EXPECT_EQ(surface.nx(), 2);
  EXPECT_EQ(surface.ny(), 2);
  // Exact: each token parses to the correctly rounded double of its decimal.
  EXPECT_EQ(surface.heights()(0, 0), 3.69862e-7);
  EXPECT_EQ(surface.heights()(0, 1), 2.5);
  EXPECT_EQ(surface.heights()(1, 0), -1.0);
}

// The reader's values against the C library's strtod, bit for bit, on every token strtod parses to a finite
// double without a range error: the awkward decimals (signs, exponents in every spelling, denormals, halfway
// cases, long mantissas) and seeded random ones, in rows ended by LF, CRLF and lone CRs with tabs, blank
// lines and trailing blanks between them (the line splitting and the number parsing read a whole-file
// buffer).
TEST_F(TopographyIoFiles, ValuesAreStrtodsBitForBitWhateverTheLineEnds) {
  std::vector<std::string> tokens = {"1",
                                     "-0",
                                     "0.0",
                                     "+2.5E+00",
                                     ".5",
                                     "5.",
                                     "-.5e-3",
                                     "+.25",
                                     "0000123.4500",
                                     "1E5",
                                     "1e+005",
                                     "3.69862e-007",
                                     "123456789012345678901234567890",
                                     "0.1000000000000000055511151231257827021181583404541015625",
                                     "9007199254740993",
                                     "2.4703282292062327e-324",
                                     "4.9406564584124654e-324",
                                     "1e-320",
                                     "2.2250738585072011e-308",
                                     "2.2250738585072014e-308",
                                     "1.7976931348623157e308",
                                     "1.7976931348623158e308",
                                     "-6.02214076E23"};
  std::mt19937_64 random(42);
  std::uniform_int_distribution<int> exponent(-330, 310), digits(1, 40), format(0, 2);
  while (tokens.size() < 4096) {
    char text[64];
    if (format(random) == 0) {  // a random bit pattern at full precision
      const double value = std::bit_cast<double>(random());
      if (!std::isfinite(value)) continue;
      std::snprintf(text, sizeof text, "%.17g", value);
    } else {  // a random decimal mantissa of 1-40 digits and a random exponent
      std::string mantissa = random() % 2 ? "-" : "";
      const int count = digits(random);
      for (int k = 0; k < count; ++k)
        mantissa += static_cast<char>('0' + random() % 10);
      if (count > 1) mantissa.insert(mantissa.size() - static_cast<std::size_t>(random() % count), ".");
      std::snprintf(text, sizeof text, "%s%c%d", mantissa.c_str(), format(random) == 1 ? 'e' : 'E',
                    exponent(random));
    }
    tokens.emplace_back(text);
  }
  // The tokens strtod reads whole, to a finite value, without ERANGE: the reader must give its bits.
  std::vector<std::string> kept;
  std::vector<double> expected;
  for (const std::string& token : tokens) {
    errno = 0;
    char* end = nullptr;
    const double value = std::strtod(token.c_str(), &end);
    if (errno == 0 && *end == '\0' && std::isfinite(value)) {
      kept.push_back(token);
      expected.push_back(value);
    }
  }
  ASSERT_GT(kept.size(), 3000u);  // the random decimals mostly land in range
  const Index columns = 8, rows = static_cast<Index>(kept.size()) / columns;
  const std::vector<std::string> row_ends = {"\n",    "\r\n",     "\r",   " \t\r\n",
                                             "\t \n", "\r\n\r\n", "\r\r", "\n \t\n"};
  std::string text = "# contactbench surface v1\r\n# nx=" + std::to_string(columns) +
                     " ny=" + std::to_string(rows) + " lx=1e-6 ly=1e-6 periodic=false unit=m\r";
  for (Index row = 0; row < rows; ++row) {
    text += row % 3 ? "\t" : "";
    for (Index column = 0; column < columns; ++column)
      text += kept[static_cast<std::size_t>(row * columns + column)] + (column % 2 ? "\t" : "  ");
    text += row_ends[static_cast<std::size_t>(row) % row_ends.size()];
  }
  const Surface surface = read_topography(write("tricky.txt", text));
  ASSERT_EQ(surface.nx(), columns);
  ASSERT_EQ(surface.ny(), rows);
  for (Index row = 0; row < rows; ++row)
    for (Index column = 0; column < columns; ++column) {
      const std::size_t k = static_cast<std::size_t>(row * columns + column);
      // Exact: bit patterns, so that -0 and +0 differ too.
      ASSERT_EQ(std::bit_cast<std::uint64_t>(surface.heights()(row, column)),
                std::bit_cast<std::uint64_t>(expected[k]))
          << kept[k];
    }
  // Lone CRs end lines as LF does: a bad token is named on its own line.
  TopographyReadOptions options;
  options.lx = 1e-6;
  expect_input_error(write("lone_cr.txt", "1 2\r\r3 x\r"), 3, "'x' is not a number", options);
  // Hexadecimal floats, which strtod also reads, stay refused as before: the readers take decimals only.
  expect_input_error(write("hex.txt", "1 0x1p3\n"), 1, "'0x1p3' is not a number", options);
}

// Rows parsed on two threads (a header that states the size, TopographyReadOptions::threads): the same bits,
// and for a defective file the same first defect named, as on one thread.
TEST_F(TopographyIoFiles, RowsParsedOnTwoThreadsGiveTheSameValuesAndMessages) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> height(-1e-6, 1e-6);
  HeightMap heights(37, 29);
  for (Index row = 0; row < heights.rows(); ++row)
    for (Index column = 0; column < heights.cols(); ++column)
      heights(row, column) = height(random);
  const fs::path file = folder_ / "surface.txt";
  write_surface(file, Surface(Grid{29, 37, 1e-6, 1e-6, false}, heights));
  TopographyReadOptions two_threads;
  two_threads.threads = 2;
  // Exact: each token is parsed by the same function, only on another thread.
  EXPECT_EQ(bits_of(read_topography(file, two_threads).heights()), bits_of(heights));
  const std::string header = "# contactbench surface v1\n# nx=3 ny=4 lx=1e-6 ly=1e-6 periodic=false unit=m\n";
  const std::string good = "1 2 3\n";
  for (const auto& [name, rows, line, reason] :
       {std::tuple{"token.txt", good + "1 2 3\n1 x 3\n1 2 y\n", 5, "'x' is not a number"},
        std::tuple{"short_row.txt", good + good + "1 2\n1 2 z\n", 5, "row has 2 values"},
        std::tuple{"long_row.txt", good + good + good + "1 2 3 4\n", 6, "row has 4 values"},
        std::tuple{"nan.txt", good + good + "nan 2 3\n" + good, 0, "1 of 12 points"}}) {
    SCOPED_TRACE(name);
    expect_input_error(write(name, header + rows), line, reason, two_threads);
    expect_input_error(write(name, header + rows), line, reason);
  }
}

// Files beyond the 64 KiB that detection reads first: a format named by the first line is detected from it,
// every other from the whole file, as a small file is.
TEST_F(TopographyIoFiles, LargeFilesAreDetectedAsSmallOnesAre) {
  std::string matrix, points;
  for (int row = 0; row < 200; ++row) {
    for (int column = 0; column < 200; ++column) {
      matrix += std::to_string(row * 200 + column) + "e-9 ";
      points +=
          std::to_string(column) + " " + std::to_string(row) + " " + std::to_string(row + column) + "\n";
    }
    matrix += "\n";
  }
  ASSERT_GT(matrix.size(), std::size_t{1} << 16);
  ASSERT_GT(points.size(), std::size_t{1} << 16);
  const std::string one_long_row(70000, '1');  // a first line longer than the head: read whole
  EXPECT_EQ(detect_topography_format(write("matrix.txt", matrix)), TopographyFormat::plain_matrix);
  EXPECT_EQ(detect_topography_format(write("points.txt", points)), TopographyFormat::xyz_points);
  EXPECT_EQ(detect_topography_format(write("long_row.txt", one_long_row + "\n" + one_long_row + "\n")),
            TopographyFormat::plain_matrix);
  EXPECT_EQ(detect_topography_format(write("gwyddion.txt", "# Width: 1 um\n# Height: 1 um\n" + matrix)),
            TopographyFormat::gwyddion);
  EXPECT_EQ(detect_topography_format(write("interferometer.txt", "h=200 w=200\n" + matrix)),
            TopographyFormat::interferometer);
  EXPECT_EQ(detect_topography_format(write("project.txt",
                                           "\r\n# contactbench surface v1\r\n# nx=200 ny=200 lx=1 ly=1 "
                                           "periodic=false unit=m\r\n" +
                                               matrix)),
            TopographyFormat::project);
  // A project file's reading agrees with its detection; a binary magic decides whatever follows it.
  EXPECT_EQ(read_topography(folder_ / "project.txt").heights()(199, 199), 39999e-9);
  EXPECT_EQ(detect_topography_format(write("npy_magic.txt", "\x93NUMPY" + matrix)), TopographyFormat::npy);
}

TEST_F(TopographyIoFiles, GwyddionAcceptsBothMicroSignsAndUm) {
  for (const std::string unit : {"\u00b5m", "\u03bcm", "um"}) {
    const fs::path file =
        write("gwyddion.txt", "# Channel: Height\n# Width: 10.00 " + unit + "\n# Height: 5 " + unit +
                                  "\n# Value units: nm\n1 2\n3 4\n");
    const Surface surface = read_topography(file);
    // One rounding of the unit conversion.
    EXPECT_NEAR(surface.grid().lx, 10e-6, unit_conversion_rounding * 10e-6) << unit;
    EXPECT_NEAR(surface.grid().ly, 5e-6, unit_conversion_rounding * 5e-6) << unit;
    // Exact: the reader forms the same product (value times the unit's size in metres).
    EXPECT_EQ(surface.heights()(1, 0), 3 * 1e-9) << unit;
  }
}

TEST_F(TopographyIoFiles, InterferometerWithoutFactorUsesALengthDataUnit) {
  const fs::path file = write("interferometer.txt", "h=2 w=3\npixel size=1 um\ndata unit=nm\n1 2 3\n4 5 6\n");
  const Surface surface = read_topography(file);
  EXPECT_EQ(surface.nx(), 3);
  EXPECT_EQ(surface.ny(), 2);
  // Exact: the reader forms the same products.
  EXPECT_EQ(surface.grid().lx, 3 * 1e-6);
  EXPECT_EQ(surface.heights()(1, 2), 6 * 1e-9);
}

TEST_F(TopographyIoFiles, GivenSizesMustAgreeWithTheFile) {
  const fs::path file = write("interferometer.txt", "h=2 w=2\npixel size=2 um\ndata unit=m\n1 2\n3 4\n");
  TopographyReadOptions options;
  options.lx = 4e-6 * (1 + 1e-7);  // within the contract's 1e-6 relative
  EXPECT_NO_THROW(read_topography(file, options));
  options.lx = 4.1e-6;
  expect_input_error(file, 2, "4.1e-06", options);
  expect_input_error(file, 2, "must agree", options);
}

// --- Bad inputs: each names the file and the line. ---

TEST_F(TopographyIoFiles, EmptyFileIsRejected) {
  expect_input_error(write("empty.txt", ""), 0, "no data rows");
  expect_input_error(write("blank.txt", "\r\n \t\n\n"), 0, "no data rows");
  EXPECT_THROW(detect_topography_format(folder_ / "empty.txt"), InputError);
}

TEST_F(TopographyIoFiles, HeaderWithoutDataRowsIsRejected) {
  expect_input_error(write("header_only.txt", "h=2 w=2\npixel size=1 um\ndata unit=m\n"), 0, "no data rows");
}

TEST_F(TopographyIoFiles, RaggedRowIsRejected) {
  TopographyReadOptions options;
  options.lx = 1e-6;
  const fs::path file = write("ragged.txt", "1 2 3\n4 5 6\n7 8\n");
  expect_input_error(file, 3, "2 values", options);
  expect_input_error(file, 3, "(line 1) has 3", options);
}

TEST_F(TopographyIoFiles, NonNumericTokenIsRejectedAndQuoted) {
  TopographyReadOptions options;
  options.lx = 1e-6;
  // Blank lines still count: the bad token is on line 3.
  expect_input_error(write("word.txt", "1 2\n\n3 abc\n"), 3, "'abc'", options);
  expect_input_error(write("two_points.txt", "1 2\n3 1.5.3\n"), 2, "'1.5.3' is not a number", options);
  // A comma separates values (CSV); a value with a blank inside is not a number.
  expect_input_error(write("comma.txt", "1,5 2\n"), 1, "'5 2' is not a number", options);
}

TEST_F(TopographyIoFiles, NanAndInfInAMatrixAreInvalidPoints) {
  // docs/formats.md "invalid points": refused with their count by default, filled on request.
  TopographyReadOptions options;
  options.lx = 1e-6;
  options.unit = "m";
  expect_input_error(write("nan.txt", "1 2\n3 4\n5 NaN\n"), 0, "1 of 6 points", options);
  expect_input_error(write("inf.txt", "1 -inf\n2 3\n"), 0, "1 of 4 points", options);
  options.fill = FillMethod::mean;
  // The mean of 2 and 3 and 1, exact in binary.
  EXPECT_EQ(read_topography(write("inf.txt", "1 -inf\n2 3\n"), options).heights()(0, 1), 2.0);
}

TEST_F(TopographyIoFiles, NanAndInfWithAHeaderAreInvalidPoints) {
  // docs/formats.md "invalid points": Inf is an invalid point in every format that can hold it, the text
  // formats with a header included (Gwyddion's export writes unmeasured points as NaN).
  const std::string gwyddion = "# Width: 1 um\n# Height: 1 um\n# Value units: nm\n1 -inf\n2 3\n";
  const std::string interferometer = "h=2 w=2\npixel size=0.5 um\ndata unit=nm\n1 NaN\n2 3\n";
  for (const auto& [name, text] :
       {std::pair{"gwyddion_inf.txt", gwyddion}, std::pair{"interferometer_nan.txt", interferometer}}) {
    SCOPED_TRACE(name);
    expect_input_error(write(name, text), 0, "1 of 4 points of channel 'height' are invalid");
    TopographyReadOptions options;
    options.fill = FillMethod::mean;
    const TopographyReading reading = read_topography_reading(write(name, text), options);
    // The mean of 1, 2 and 3 nm, filled in metres: exact to one rounding of the nm scale.
    EXPECT_NEAR(reading.surface.heights()(0, 1), 2e-9, 1e-24);
    EXPECT_EQ(reading.surface.grid().lx, 1e-6);
  }
  // A finite value is refused, naming the line, when the height factor pushes it beyond the largest double.
  expect_input_error(write("scaled.txt",
                           "h=1 w=1\npixel size=1 um\ndata unit=rad\n"
                           "height conversion factor (-> m)=1e10\n1e300\n"),
                     5, "not finite");
  TopographyReadOptions options;
  options.lx = 1e-6;
  expect_input_error(write("overflow.txt", "1 2\n1e999 3\n"), 2, "out of the range", options);
  // The project's own format alike: its writer writes finite heights, but a file edited by hand may not.
  expect_input_error(write("project_nan.txt",
                           "# contactbench surface v1\n# nx=2 ny=1 lx=1e-6 ly=5e-7 periodic=false unit=m\n"
                           "1 nan\n"),
                     0, "1 of 2 points of channel 'height' are invalid");
}

TEST_F(TopographyIoFiles, MissingSizeIsRejected) {
  expect_input_error(write("plain.txt", "1 2\n3 4\n"), 0, "--size");
  expect_input_error(write("no_pixel.txt", "h=2 w=2\ndata unit=m\n1 2\n3 4\n"), 1, "pixel size");
  expect_input_error(write("no_width.txt", "# Height: 1 um\n# Value units: m\n1 2\n"), 1, "Width");
}

TEST_F(TopographyIoFiles, NonPositiveSizeIsRejected) {
  expect_input_error(write("zero_pixel.txt", "h=1 w=2\npixel size=0 m\ndata unit=m\n1 2\n"), 2, "> 0");
  expect_input_error(write("negative_width.txt",
                           "# Channel: Z\n# Width: -10 \u00b5m\n# Height: 10 \u00b5m\n"
                           "# Value units: m\n1 2\n"),
                     2, "> 0");
  expect_input_error(
      write("infinite_height.txt", "# Width: 10 um\n# Height: inf um\n# Value units: m\n1 2\n"), 2, "> 0");
  TopographyReadOptions options;
  options.lx = -1e-6;
  expect_input_error(write("plain.txt", "1 2\n"), 0, "finite size > 0", options);
}

TEST_F(TopographyIoFiles, UnknownUnitIsRejected) {
  // The message lists the accepted units.
  expect_input_error(write("furlong.txt", "h=1 w=2\npixel size=3 furlong\ndata unit=m\n1 2\n"), 2,
                     "'furlong'");
  expect_input_error(write("furlong.txt", "h=1 w=2\npixel size=3 furlong\ndata unit=m\n1 2\n"), 2,
                     "m, mm, um, \u00b5m, \u03bcm, nm");
  expect_input_error(write("no_unit.txt", "h=1 w=2\npixel size=3\ndata unit=m\n1 2\n"), 2, "no unit");
  expect_input_error(write("volts.txt", "# Width: 1 um\n# Height: 1 um\n# Value units: V\n1 2\n"), 3, "'V'");
  // Radians are heights only with a conversion factor.
  expect_input_error(write("radians.txt", "h=1 w=2\npixel size=1 um\ndata unit=rad\n1 2\n"), 3, "'rad'");
}

TEST_F(TopographyIoFiles, HeaderCountsMustMatchTheData) {
  const std::string header = "pixel size=1 um\ndata unit=m\n";
  expect_input_error(write("few_rows.txt", "h=3 w=2\n" + header + "1 2\n3 4\n"), 1, "has 2 data rows");
  expect_input_error(write("many_rows.txt", "h=1 w=2\n" + header + "1 2\n3 4\n"), 5, "h=1");
  expect_input_error(write("few_columns.txt", "h=2 w=3\n" + header + "1 2\n3 4\n"), 4, "w=3");
  expect_input_error(write("project.txt",
                           "# contactbench surface v1\n"
                           "# nx=3 ny=1 lx=1e-6 ly=1e-6 periodic=false unit=m\n1 2\n"),
                     3, "nx=3");
}

TEST_F(TopographyIoFiles, ProjectHeaderDefectsAreRejected) {
  expect_input_error(
      write("version.txt", "# contactbench surface v2\n# nx=1 ny=1 lx=1 ly=1 periodic=false unit=m\n1\n"), 1,
      "v1");
  expect_input_error(
      write("no_ly.txt", "# contactbench surface v1\n# nx=1 ny=1 lx=1 periodic=false unit=m\n1\n"), 2, "ly=");
  expect_input_error(
      write("periodic.txt", "# contactbench surface v1\n# nx=1 ny=1 lx=1 ly=1 periodic=yes unit=m\n1\n"), 2,
      "'yes'");
}

TEST_F(TopographyIoFiles, MissingFileIsRejected) {
  const fs::path file = folder_ / "does_not_exist.txt";
  expect_input_error(file, 0, "no such file");
  EXPECT_THROW(detect_topography_format(file), InputError);
  expect_input_error(folder_, 0, "folder");
}

}  // namespace
}  // namespace contactbench
