// A project file read a few rows at a time (core/topography_rows.hpp, the reader of slabs under mpiexec):
// the heights read_topography returns, bit for bit, in any chunks; the same refusals for a defective file;
// nothing for the formats and options it leaves to the whole-file reader.
#include "contactbench/core/topography_rows.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "test_folder.hpp"

namespace contactbench {
namespace {

class TopographyRows : public testing::FolderTest {
 protected:
  TopographyRows() : FolderTest("cb_rows_") {}

  // A 13 x 11 surface written in the project's format (its heights' shortest round-trip decimals).
  std::filesystem::path project_file() const {
    const Surface surface = generate_surface({.nx = 13, .ny = 11, .lx = 1e-4, .ly = 0.8e-4, .periodic = true},
                                             {.sigma = 1e-6, .hurst = 0.7, .qr = 1e5, .qs = std::nullopt}, 3);
    const std::filesystem::path path = folder_ / "surface.txt";
    write_surface(path, surface);
    return path;
  }

  static std::string text_of(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }
};

TEST_F(TopographyRows, ReadsTheWholeFileReadersHeightsBitForBitInAnyChunks) {
  const std::filesystem::path path = project_file();
  const Surface whole = read_topography(path);
  for (const Index chunk : {Index{1}, Index{4}, Index{11}}) {
    auto reader = TopographyRowReader::open(path, {});
    ASSERT_TRUE(reader);
    EXPECT_EQ(reader->grid().nx, 13);
    EXPECT_EQ(reader->grid().ny, 11);
    EXPECT_EQ(reader->grid().lx, whole.grid().lx);
    EXPECT_TRUE(reader->grid().periodic);
    HeightMap heights(11, 13);
    for (Index row = 0; row < 11; row += chunk)
      reader->read(std::min(chunk, 11 - row), heights.data() + row * 13);
    reader->finish();
    EXPECT_TRUE((heights == whole.heights()).all()) << "chunks of " << chunk;  // bit for bit
  }
  TopographyReadOptions options;
  options.periodic = false;
  EXPECT_FALSE(TopographyRowReader::open(path, options)->grid().periodic);
}

TEST_F(TopographyRows, RefusesADefectiveFileNamingTheLine) {
  const std::string text = text_of(project_file());
  // Line 3 is the first row: drop its last value; then drop the last row; then add one.
  const std::size_t row_end = text.find('\n', text.find('\n', text.find('\n') + 1) + 1);
  const std::string short_row = text.substr(0, text.rfind(' ', row_end)) + text.substr(row_end);
  const std::string missing_row = text.substr(0, text.rfind('\n', text.size() - 2) + 1);
  const std::string extra_row = text + text.substr(text.rfind('\n', text.size() - 2) + 1);
  const auto read_all = [](const std::filesystem::path& path) {
    auto reader = TopographyRowReader::open(path, {});
    std::vector<Real> row(13);
    for (Index k = 0; k < 11; ++k)
      reader->read(1, row.data());
    reader->finish();
  };
  for (const auto& [name, content, expected] :
       {std::tuple<std::string, std::string, std::string>{"short.txt", short_row, ":3: row has 12 values"},
        {"missing.txt", missing_row, "promises 11 rows but the file has 10 data rows"},
        {"extra.txt", extra_row, ":14: more data rows than the header's ny=11"}}) {
    try {
      read_all(write(name, content));
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
  // An invalid point: read_topography refuses it without a fill, and so does the reader of rows.
  const std::string with_nan = text.substr(0, text.rfind(' ', row_end) + 1) + "nan" + text.substr(row_end);
  EXPECT_THROW(read_all(write("nan.txt", with_nan)), InputError);
}

TEST_F(TopographyRows, LeavesOtherFormatsAndOptionsToTheWholeFileReader) {
  const std::filesystem::path path = project_file();
  TopographyReadOptions fill;
  fill.fill = FillMethod::mean;
  EXPECT_FALSE(TopographyRowReader::open(path, fill));
  TopographyReadOptions level;
  level.level = Levelling::plane;
  EXPECT_FALSE(TopographyRowReader::open(path, level));
  EXPECT_FALSE(TopographyRowReader::open(write("matrix.csv", "1e-6,2e-6\n3e-6,4e-6\n"), {}));
  // A size that disagrees with the header's is the whole-file reader's error.
  TopographyReadOptions wrong;
  wrong.lx = 2e-4;
  EXPECT_THROW(TopographyRowReader::open(path, wrong), InputError);
}

}  // namespace
}  // namespace contactbench
