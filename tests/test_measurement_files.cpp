// A user's own measurement files through the contactbench binary (issue 37, docs/formats.md): nothing
// destroyed (convert never writes over its input nor under a name it cannot write), no silent wrong surface
// (an x y z list read as a grid, a unit required when Sq is implausible for metres), every refusal one line
// naming the file and the cause, and the input byte for byte as it was (its MD5 before and after).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "contactbench/core/formats/md5.hpp"
#include "test_constants.hpp"

namespace contactbench {
namespace {

namespace fs = std::filesystem;

using testing::kFormatSamples;

using testing::CommandResult;
using testing::slurp;

class MeasurementFiles : public testing::CliTest {
 protected:
  MeasurementFiles() : CliTest("contactbench_measurement_files_") {}

  // A copy of a sample in the test's folder, for the commands to (try to) damage.
  fs::path copy_sample(const std::string& name, const std::string& as) const {
    const fs::path copy = folder_ / as;
    fs::copy_file(kFormatSamples / name, copy);
    return copy;
  }
};

std::string md5_of(const fs::path& file) {
  return formats::md5_hex(slurp(file));
}

double json_number(const std::string& json, const std::string& key) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + key + "\": ([-+0-9.eE]+)")))
    throw std::runtime_error("no number " + key + " in " + json);
  return std::stod(match[1]);
}

// The command failed with one line of error that names `file` and says `cause`.
void expect_refusal(const CommandResult& result, const fs::path& file, const std::string& cause) {
  EXPECT_EQ(result.status, 1) << result.err;
  EXPECT_NE(result.err.find(file.string()), std::string::npos) << "file not named: " << result.err;
  EXPECT_NE(result.err.find(cause), std::string::npos) << "expected '" << cause << "' in: " << result.err;
  EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;
}

TEST_F(MeasurementFiles, ConvertRefusesItsInputAsOutputByAnyName) {
  const fs::path input = copy_sample("sur-3.sur", "a.sur");
  const std::string before = md5_of(input);
  fs::create_hard_link(input, folder_ / "link.sur");
  for (const fs::path& output : {input, folder_ / "." / "a.sur", folder_ / "link.sur"}) {
    const CommandResult result = run("convert " + input.string() + " " + output.string() + " --fill mean");
    expect_refusal(result, input, "is the input file");
    EXPECT_EQ(md5_of(input), before) << output;
  }
}

TEST_F(MeasurementFiles, ConvertRefusesAnExtensionItCannotWriteBeforeReading) {
  const fs::path input = copy_sample("metropro-1.dat", "m.dat");
  const std::string before = md5_of(input);
  for (const std::string name : {"out.sur", "out.dat", "out.di", "out", "out.csv"}) {
    const fs::path output = folder_ / name;
    const CommandResult result = run("convert " + input.string() + " " + output.string());
    expect_refusal(result, output,
                   ".x3p (ISO 25178-72, float64), .npy (NumPy float64), .gwy (Gwyddion, float64), .txt");
    EXPECT_FALSE(fs::exists(output)) << name;
  }
  EXPECT_EQ(md5_of(input), before);
}

TEST_F(MeasurementFiles, ConvertWritesGwyddionThatReadsBackTheSameHeights) {
  const fs::path input = kFormatSamples / "metropro-1.dat";
  const fs::path output = folder_ / "m.gwy";
  ASSERT_EQ(run("convert " + input.string() + " " + output.string()).status, 0);
  const CommandResult original = run("stats " + input.string());
  const CommandResult copy = run("stats " + output.string());
  ASSERT_EQ(copy.status, 0) << copy.err;
  // The same doubles: the same shortest decimals, printed by the same code.
  for (const char* key : {"nx", "ny", "lx", "ly", "mean", "sq", "m2x"})
    EXPECT_EQ(json_number(copy.out, key), json_number(original.out, key)) << key;
}

TEST_F(MeasurementFiles, PointListIsReadOnItsGrid) {
  // xyz-1.txt (data/formats/README.md): x slow, y fast, 4 x 4 points at step 1; h = 2 at (1, 1) and (1, 2).
  const fs::path input = kFormatSamples / "xyz-1.txt";
  const std::string before = md5_of(input);
  const CommandResult result = run("stats " + input.string() + " --unit um");
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_NE(result.out.find("\"format\": \"xyz_points\""), std::string::npos) << result.out;
  EXPECT_EQ(json_number(result.out, "nx"), 4);
  EXPECT_EQ(json_number(result.out, "ny"), 4);
  // Size = count x step = 4 um; the unit scales coordinates and heights alike (one rounding).
  EXPECT_NEAR(json_number(result.out, "lx"), 4e-6, 1e-15 * 4e-6 * 4);
  EXPECT_NEAR(json_number(result.out, "ly"), 4e-6, 1e-15 * 4e-6 * 4);
  // The reference rms to 1e-9 relative (the reference's 10 digits); the mean 1.125 um.
  EXPECT_NEAR(json_number(result.out, "sq"), 0.3307189139e-6, 1e-9 * 0.3307189139e-6);
  EXPECT_NEAR(json_number(result.out, "mean"), 1.125e-6, 1e-12 * 1.125e-6);
  EXPECT_EQ(md5_of(input), before);
}

TEST_F(MeasurementFiles, PointListHeightsLandWhereTheirCoordinatesSay) {
  // Listed out of order, y slow: h(x, y) = x + 10 y (in nm); the project's format written by convert puts
  // row y, column x. Each value divided by 1e9 is the double nearest its decimal, so the text is exact.
  std::string text;
  for (int y = 2; y >= 0; --y)
    for (int x = 0; x < 4; ++x)
      text += std::to_string(x * 5) + " " + std::to_string(y * 5) + " " + std::to_string(x + 10 * y) + "\n";
  const fs::path input = write("points.xyz", text);
  const fs::path output = folder_ / "points.txt";
  const CommandResult result = run("convert " + input.string() + " " + output.string() + " --unit nm");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string written = slurp(output);
  EXPECT_NE(written.find("nx=4 ny=3 lx=2e-08 ly=1.5e-08"), std::string::npos) << written;
  EXPECT_NE(written.find("\n0 1e-09 2e-09 3e-09\n1e-08 1.1e-08 1.2e-08 1.3e-08\n"), std::string::npos)
      << written;
}

TEST_F(MeasurementFiles, IrregularPointListsAreRefusedSayingSo) {
  const fs::path scattered = write("scattered.xyz", "0 0 1\n0.3 1.7 2\n2.9 0.4 1\n1.1 2.2 3\n");
  const std::string before = md5_of(scattered);
  expect_refusal(run("stats " + scattered.string() + " --unit um"), scattered, "irregular point list");
  EXPECT_EQ(md5_of(scattered), before);
  // A full grid in count whose x steps are uneven (0, 1, 3).
  const fs::path uneven = write("uneven.txt", "0 0 1\n1 0 1\n3 0 1\n0 1 1\n1 1 1\n3 1 2\n");
  expect_refusal(run("stats " + uneven.string() + " --unit um"), uneven,
                 "irregular point list: the x values are not evenly spaced");
  // One grid point given twice, another missing.
  const fs::path twice = write("twice.xyz", "0 0 1\n1 0 1\n1 0 2\n1 1 1\n");
  expect_refusal(run("stats " + twice.string() + " --unit um"), twice, "is listed twice");
}

TEST_F(MeasurementFiles, ImplausibleMetresNeedAUnitAndTheMessageSuggestsIt) {
  // Heights of a few nanometres written in nm: Sq 5.8 "m" taken as metres.
  const fs::path input = write("nm.txt", "0 10\n-3 5\n12 -7\n");
  const std::string before = md5_of(input);
  const CommandResult refused = run("stats " + input.string() + " --size 1e-5");
  expect_refusal(refused, input, "states no unit");
  EXPECT_NE(refused.err.find("likely um (Sq 6.82 um) or nm (Sq 6.82 nm)"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--unit"), std::string::npos) << refused.err;
  const CommandResult read = run("stats " + input.string() + " --size 1e-5 --unit nm");
  ASSERT_EQ(read.status, 0) << read.err;
  // Sq of {0, 10, -3, 5, 12, -7} nm about their mean 17/6: 6.8170538 nm (Python's
  // statistics.pstdev); 1e-12 relative: stats prints the shortest decimal of a sum of six squares.
  EXPECT_NEAR(json_number(read.out, "sq"), 6.8170537787391865e-9, 1e-12 * 6.8170537787391865e-9);
  EXPECT_NE(read.out.find("\"unit\": \"nm\""), std::string::npos) << read.out;
  // Far too smooth for metres: below 1 pm.
  const fs::path tiny = write("tiny.txt", "0 1e-14\n2e-14 0\n");
  expect_refusal(run("stats " + tiny.string() + " --size 1e-5"), tiny, "if they really are metres");
  // A file that states its unit does not take another.
  const fs::path x3p = kFormatSamples / "x3p-2.x3p";
  expect_refusal(run("stats " + x3p.string() + " --unit nm"), x3p, "states its own unit");
  EXPECT_EQ(md5_of(input), before);
}

TEST_F(MeasurementFiles, CsvAndSemicolonMatricesAreRead) {
  // The same 2 x 3 heights in um three ways: commas, semicolons with decimal commas, blanks.
  const fs::path csv = write("m.csv", "1.5,2,3\n4,5,6.25\n");
  const fs::path semicolons = write("m2.csv", "1,5; 2; 3\r\n4;5;6,25\r\n");
  const fs::path blanks = write("m3.txt", "1.5 2 3\n4 5 6.25\n");
  std::string reference;
  for (const fs::path& file : {blanks, csv, semicolons}) {
    const CommandResult result = run("stats " + file.string() + " --size 3e-6 --unit um");
    ASSERT_EQ(result.status, 0) << file << result.err;
    EXPECT_EQ(json_number(result.out, "nx"), 3);
    EXPECT_EQ(json_number(result.out, "ny"), 2);
    const std::string sq = std::to_string(json_number(result.out, "sq"));
    if (reference.empty()) reference = result.out.substr(result.out.find("\"mean\""), 60);
    EXPECT_EQ(result.out.substr(result.out.find("\"mean\""), 60), reference) << file;
  }
  const fs::path empty_value = write("gap.csv", "1,,3\n4,5,6\n");
  expect_refusal(run("stats " + empty_value.string() + " --size 3e-6 --unit um"), empty_value,
                 "an empty value between two separators");
}

TEST_F(MeasurementFiles, MomentsStageErrorsNameTheFile) {
  // Heights of 1e200 m (said to be metres) overflow the spectral sums.
  const fs::path input = write("huge.txt", "1e200 -1e200\n3e200 0\n");
  expect_refusal(run("stats " + input.string() + " --size 1e-5 --unit m"), input, "spectral moments");
}

TEST_F(MeasurementFiles, SceneUnitKeyScalesAMatrix) {
  const fs::path matrix = write("nm.txt", "0 10 2 4\n-3 5 1 1\n12 -7 0 3\n8 2 -2 6\n");
  const std::string scene_head = "name = \"unit\"\n[surface]\nfile = \"nm.txt\"\nsize = 1e-6\n";
  const std::string scene_tail =
      "[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-3]\n[methods.persson]\nanisotropy = "
      "\"average\"\n";
  const fs::path refused_scene = write("refused.toml", scene_head + scene_tail);
  const CommandResult refused =
      run("run " + refused_scene.string() + " --out " + (folder_ / "r1").string() + " --no-plots --quiet");
  EXPECT_EQ(refused.status, 1) << refused.err;
  EXPECT_NE(refused.err.find("nm.txt: a plain_matrix states no unit"), std::string::npos) << refused.err;
  const fs::path scene = write("nm.toml", scene_head + "unit = \"nm\"\n" + scene_tail);
  const CommandResult result =
      run("run " + scene.string() + " --out " + (folder_ / "r2").string() + " --no-plots --quiet");
  ASSERT_EQ(result.status, 0) << result.err;
  // The summary's resolved scene records the unit.
  const std::string summary = slurp(folder_ / "r2" / "summary.json");
  EXPECT_NE(summary.find("\"unit\": \"nm\""), std::string::npos) << summary;
}

TEST_F(MeasurementFiles, LineScansGiveProfileStatisticsToTheirReferenceValues) {
  // data/formats/README.md: the piecewise-linear rq and rms slope SurfaceTopography's tests assert, and the
  // per-point rms; the references carry 7 or 8 digits, so they are compared to half a unit of their last one.
  struct Case {
    const char* file;
    const char* unit;
    const char* source;
    double points, length, rq, rq_points, rms_slope;
    double tolerance, slope_tolerance;  // half a unit of the reference's last digit, relative
  };
  for (const Case& c :
       {Case{"csv-1.csv", " --unit um", "x h text", 8, 0.2703e-6, 0.03957452e-6, 0.04722499e-6, 0, 1.3e-7, 0},
        Case{"xy-1.txt", " --unit um", "x h text", 132, 187.190431e-6, 3.0585577e-6, 3.1268354e-6, 0.43824152,
             1.7e-8, 1.2e-8},
        Case{"dektak-1.csv", "", "dektak", 9600, 1.4998e-3, 4.763596e-6, 0, 0.015448, 1.1e-7, 3.3e-5}}) {
    const fs::path input = kFormatSamples / c.file;
    const std::string before = md5_of(input);
    const CommandResult result = run("stats " + input.string() + c.unit);
    ASSERT_EQ(result.status, 0) << c.file << result.err;
    EXPECT_NE(result.out.find(std::string("\"source\": \"") + c.source + "\""), std::string::npos)
        << result.out;
    EXPECT_EQ(json_number(result.out, "points"), c.points) << c.file;
    EXPECT_NEAR(json_number(result.out, "length"), c.length, 1e-12 * c.length) << c.file;
    EXPECT_NEAR(json_number(result.out, "rq"), c.rq, c.tolerance * c.rq) << c.file;
    if (c.rq_points > 0) {
      EXPECT_NEAR(json_number(result.out, "rq_points"), c.rq_points, c.tolerance * c.rq_points) << c.file;
    }
    if (c.rms_slope > 0) {
      EXPECT_NEAR(json_number(result.out, "rms_slope"), c.rms_slope, c.slope_tolerance * c.rms_slope)
          << c.file;
    }
    EXPECT_EQ(md5_of(input), before) << c.file;
  }
  // Dektak names its units (um) in the column header: another unit is refused.
  const fs::path dektak = kFormatSamples / "dektak-1.csv";
  expect_refusal(run("stats " + dektak.string() + " --unit nm"), dektak, "states the heights' unit ('um')");
}

TEST_F(MeasurementFiles, StatsOfALineScanLevelsItAndRefusesTheOptionsOfA2DFile) {
  const fs::path input = kFormatSamples / "xy-1.txt";
  const CommandResult raw = run("stats " + input.string() + " --unit um");
  const CommandResult levelled = run("stats " + input.string() + " --unit um --level plane");
  ASSERT_EQ(levelled.status, 0) << levelled.err;
  EXPECT_NE(levelled.out.find("\"level\": \"plane\""), std::string::npos) << levelled.out;
  // Levelling removes a line: the rms slope changes (this scan is tilted by about 0.014 against 0.44 rms:
  // 5e-4 relative, far above the 1e-6 asked); the point count and length do not.
  EXPECT_EQ(json_number(levelled.out, "points"), json_number(raw.out, "points"));
  EXPECT_GT(std::abs(json_number(levelled.out, "rms_slope") / json_number(raw.out, "rms_slope") - 1), 1e-6);
  for (const std::string option : {"--fill mean", "--crop measured", "--align-rows mean", "--size 1e-4"}) {
    const CommandResult refused = run("stats " + input.string() + " --unit um " + option);
    EXPECT_EQ(refused.status, 1) << option;
    EXPECT_NE(refused.err.find(option.substr(0, option.find(' ')) + " is for a 2-D file"), std::string::npos)
        << refused.err;
  }
}

// The rows of a CSV the commands write, after its '#' header and column line.
std::vector<std::vector<double>> csv_rows(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(text);
  std::string line;
  bool columns = false;
  while (std::getline(in, line)) {
    if (line.starts_with('#')) continue;
    if (!columns) {
      columns = true;
      continue;
    }
    std::vector<double> row;
    std::istringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ','))
      row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

TEST_F(MeasurementFiles, StatsWritesTheProfilePsdOfAUniformScan) {
  // 512 uniform points over 100 um: a sine of 12 cycles on a smaller one of 40 (heights in metres).
  std::ostringstream scan;
  scan.precision(17);
  const int n = 512;
  const double length = 100e-6, pi = std::acos(-1.0);
  for (int k = 0; k < n; ++k) {
    const double x = length * k / n;
    scan << x << ' ' << 1e-6 * std::sin(2 * pi * 12 * x / length) + 1e-7 * std::sin(2 * pi * 40 * x / length)
         << '\n';
  }
  const fs::path input = write("uniform.txt", scan.str());
  const fs::path psd = folder_ / "psd.csv";
  const CommandResult result = run("stats " + input.string() + " --psd " + psd.string());
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string text = slurp(psd);
  EXPECT_NE(text.find("# contactbench stats " + input.string() + " --psd " + psd.string()), std::string::npos)
      << text;
  const std::vector<std::vector<double>> rows = csv_rows(text);
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(n / 2 + 1));
  // The peak sits at the big sine's wavevector 2 pi 12 / L (the lattice step is 2 pi / (n dx)); the window
  // spreads it over the neighbours only.
  std::size_t peak = 0;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (rows[k][1] > rows[peak][1]) peak = k;
  EXPECT_NEAR(rows[peak][0], 2 * pi * 12 / length, 1e-6 * rows[peak][0]);
  // Parseval, two-sided: C1(0) dq + 2 sum over 0 < q < qmax + C1(qmax) dq is the windowed mean square, which
  // the Hann window's normalisation keeps equal to rq^2 within 2 % for whole cycles (the window weighs the
  // record's middle; the profile's rq integrates the piecewise-linear profile, 0.1 % off the samples').
  const double dq = rows[1][0] - rows[0][0];
  double total = rows.front()[1] * dq + rows.back()[1] * dq;
  for (std::size_t k = 1; k + 1 < rows.size(); ++k)
    total += 2 * rows[k][1] * dq;
  const double rq = json_number(result.out, "rq");
  EXPECT_NEAR(total / (rq * rq), 1, 0.02);
  // Uneven sampling has no periodogram; the input is never the output.
  const fs::path uneven = kFormatSamples / "xy-1.txt";
  const CommandResult refused = run("stats " + uneven.string() + " --unit um --psd " + psd.string());
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("--psd needs a uniformly sampled scan"), std::string::npos) << refused.err;
  const CommandResult over = run("stats " + input.string() + " --psd " + input.string());
  EXPECT_EQ(over.status, 1);
  EXPECT_NE(over.err.find("is the input file"), std::string::npos) << over.err;
  // A surface's PSD: the radial average, one row a bin.
  const CommandResult surface = run("stats " + (kFormatSamples / "metropro-1.dat").string() + " --psd " +
                                    (folder_ / "radial.csv").string());
  ASSERT_EQ(surface.status, 0) << surface.err;
  const std::string radial = slurp(folder_ / "radial.csv");
  EXPECT_NE(radial.find("q_per_m,c_m4,modes"), std::string::npos);
  EXPECT_GT(csv_rows(radial).size(), 10u);
}

TEST_F(MeasurementFiles, ConvertAndAreaMethodsRefuseALineScanWhichDrivesTheTheories) {
  const fs::path input = kFormatSamples / "xy-1.txt";
  const std::string before = md5_of(input);
  expect_refusal(run("convert " + input.string() + " " + (folder_ / "out.txt").string() + " --unit um"),
                 input, "is a line scan (a profile along one line), not a surface");
  // A scene over the scan: Persson's theory (which reads m2 alone) runs on the isotropic surface the profile
  // samples, and says so; the BEM needs heights over an area and is refused, naming why.
  const std::string head = "name = \"scan\"\n[surface]\nfile = \"" + input.string() +
                           "\"\nunit = \"um\"\nlevel = \"plane\"\n[material]\nE = 100e9\nnu = 0.3\n[loads]\n"
                           "values = [1e-3]\n[methods.persson]\n";
  const CommandResult ran = run("run " + write("scan.toml", head).string() + " --out " +
                                (folder_ / "r").string() + " --no-plots --quiet");
  ASSERT_EQ(ran.status, 0) << ran.err;
  const std::string table = slurp(folder_ / "r" / "table.md");
  EXPECT_NE(table.find("Line scan (x h text) of 132 points over 187.2 um, unevenly sampled (no m4), levelled "
                       "plane"),
            std::string::npos)
      << table;
  const CommandResult refused = run("run " + write("bem.toml", head + "[methods.bem]\n").string() +
                                    " --out " + (folder_ / "b").string() + " --no-plots --quiet");
  EXPECT_EQ(refused.status, 1) << refused.err;
  EXPECT_NE(refused.err.find("methods.bem: the method bem needs heights over an area, and the surface is a "
                             "line scan"),
            std::string::npos)
      << refused.err;
  EXPECT_EQ(md5_of(input), before);
}

TEST_F(MeasurementFiles, CropAndRowAlignmentAreRecordedByStatsAndScenes) {
  const fs::path input = kFormatSamples / "sur-3.sur";
  const std::string before = md5_of(input);
  const CommandResult stats =
      run("stats " + input.string() + " --crop measured --align-rows median --level quadratic");
  ASSERT_EQ(stats.status, 0) << stats.err;
  EXPECT_NE(stats.out.find("\"crop\": \"measured (columns 61 to 249, rows 229 to 280)\""), std::string::npos)
      << stats.out;
  EXPECT_NE(stats.out.find("\"align_rows\": \"median\""), std::string::npos) << stats.out;
  EXPECT_NE(stats.out.find("\"level\": \"quadratic\""), std::string::npos) << stats.out;
  const fs::path scene =
      write("crop.toml", "name = \"crop\"\n[surface]\nfile = \"" + input.string() +
                             "\"\ncrop = \"measured\"\nalign_rows = \"mean\"\nlevel = \"plane\"\n"
                             "[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [1e-3]\n"
                             "[methods.persson]\nanisotropy = \"average\"\n");
  const CommandResult result =
      run("run " + scene.string() + " --out " + (folder_ / "r").string() + " --no-plots --quiet");
  ASSERT_EQ(result.status, 0) << result.err;
  const std::string summary = slurp(folder_ / "r" / "summary.json");
  EXPECT_NE(summary.find("\"crop\": \"measured\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"align_rows\": \"mean\""), std::string::npos) << summary;
  const fs::path bad = write("bad.toml", "name = \"bad\"\n[surface]\nfile = \"" + input.string() +
                                             "\"\ncrop = \"all\"\n[material]\nE = 100e9\nnu = 0.3\n[loads]\n"
                                             "values = [1e-3]\n[methods.persson]\n");
  const CommandResult refused =
      run("run " + bad.string() + " --out " + (folder_ / "b").string() + " --no-plots");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("surface.crop"), std::string::npos) << refused.err;
  EXPECT_EQ(md5_of(input), before);
}

TEST_F(MeasurementFiles, SweepAndBemPassTheReadingOptionsOn) {
  // sur-3.sur is refused for its unmeasured points unless cropped (or filled): the option must reach the
  // scene these commands build, not be dropped.
  const fs::path input = kFormatSamples / "sur-3.sur";
  const CommandResult refused = run("sweep " + input.string() + " --levels 8");
  EXPECT_EQ(refused.status, 1);
  EXPECT_NE(refused.err.find("233009 of 262144 points"), std::string::npos) << refused.err;
  const CommandResult cropped = run("sweep " + input.string() + " --levels 8 --crop measured --level plane");
  EXPECT_EQ(cropped.status, 0) << cropped.err;
  const CommandResult channel =
      run("bem " + (kFormatSamples / "di-3.di").string() + " --channel Nope --loads 1e-3");
  EXPECT_EQ(channel.status, 1);
  EXPECT_NE(channel.err.find("unknown channel 'Nope'"), std::string::npos) << channel.err;
}

TEST_F(MeasurementFiles, HelpListsEveryFormat) {
  for (const std::string command : {"stats", "convert"}) {
    const CommandResult help = run(command + " --help");
    ASSERT_EQ(help.status, 0) << help.err;
    for (const char* format :
         {".x3p", ".sdf", ".npy", ".dat", ".di", ".plu", ".sur", ".opd", ".nc", "interferometer",
          "Gwyddion text", "plain matrix", "x y z point list", "--unit"})
      EXPECT_NE(help.out.find(format), std::string::npos) << command << " --help lacks " << format;
  }
}

}  // namespace
}  // namespace contactbench
