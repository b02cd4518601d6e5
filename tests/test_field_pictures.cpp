// Field files and their pictures (app/field_picture.hpp, app/load_fields.hpp, `contactbench plot`), where a
// scene's fields land (inside --out), and the progress lines (app/run_observer.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <regex>
#include <sstream>

#include "cli_runner.hpp"
#include "contactbench/app/field_picture.hpp"
#include "contactbench/app/gnuplot_text.hpp"
#include "contactbench/app/load_area_plots.hpp"
#include "contactbench/app/run_observer.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"
#include "small_scene.hpp"

namespace contactbench {
namespace {

using testing::CliTest;
using testing::slurp;

// A 6 x 4 field with known extremes: values -2 ... 21 MPa, as a pressure in Pa.
Field small_pressure() {
  HeightMap values(4, 6);
  for (Index r = 0; r < 4; ++r)
    for (Index c = 0; c < 6; ++c)
      values(r, c) = (static_cast<Real>(r * 6 + c) - 2.0) * 1e6;
  return {Surface(Grid{.nx = 6, .ny = 4, .lx = 60e-6, .ly = 40e-6, .periodic = true}, values), "pressure",
          "Pa"};
}

// Width and height from a PNG's signature and IHDR chunk; {0, 0} when the file is not a PNG.
std::array<std::uint32_t, 2> png_size(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 24> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  static constexpr std::array<unsigned char, 8> signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature.begin(), signature.end(), head.begin()) ||
      std::string(head.begin() + 12, head.begin() + 16) != "IHDR")
    return {0, 0};
  const auto big_endian = [&](std::size_t at) {
    return (std::uint32_t{head[at]} << 24) | (std::uint32_t{head[at + 1]} << 16) |
           (std::uint32_t{head[at + 2]} << 8) | std::uint32_t{head[at + 3]};
  };
  return {big_endian(16), big_endian(20)};
}

class FieldPictures : public CliTest {
 protected:
  FieldPictures() : CliTest("cb_pictures_") {}
};

TEST_F(FieldPictures, PressureFieldSaysPascalAndIsNoSurface) {
  const auto path = folder_ / "p.txt";
  write_field(path, small_pressure());
  const std::string text = slurp(path);
  EXPECT_NE(text.find("quantity=pressure unit=Pa\n"), std::string::npos) << text.substr(0, 120);
  const Field back = read_field(path);
  EXPECT_EQ(back.quantity, "pressure");
  EXPECT_EQ(back.unit, "Pa");
  // Lossless, as the surface format: every value bit for bit.
  EXPECT_TRUE((back.values.heights() == small_pressure().values.heights()).all());
  try {
    read_topography(path);
    ADD_FAILURE() << "a pressure field read as heights";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contactbench plot"), std::string::npos) << e.what();
  }
  // A gap is a length: it reads as heights, as before.
  Field gap = small_pressure();
  gap.quantity = "gap";
  gap.unit = "m";
  gap.values = Surface(gap.values.grid(), gap.values.heights() * 1e-15);
  write_field(folder_ / "g.txt", gap);
  // Bit for bit what was written (the format is lossless).
  EXPECT_EQ(read_topography(folder_ / "g.txt").heights().maxCoeff(), 21e6 * 1e-15);
}

TEST_F(FieldPictures, ColourScaleIsTheFieldsRangeInItsUnit) {
  const ColourScale scale = colour_scale(small_pressure());
  EXPECT_EQ(scale.unit.label, "MPa");
  // -2e6 Pa and 21e6 Pa times 1e-6: exact to rounding of one product (relative 1e-15).
  EXPECT_NEAR(scale.low, -2.0, 1e-14);
  EXPECT_NEAR(scale.high, 21.0, 1e-14);
  std::ostringstream script;
  write_field_gnuplot_script(script, small_pressure(), "p.txt", "p", "p.png", "");
  const std::regex range(R"(set cbrange \[([^:\]]+):([^\]]+)\])");
  std::smatch found;
  const std::string text = script.str();
  ASSERT_TRUE(std::regex_search(text, found, range)) << text;
  EXPECT_NEAR(std::stod(found[1]), -2.0, 1e-14);
  EXPECT_NEAR(std::stod(found[2]), 21.0, 1e-14);
  EXPECT_NE(text.find("pressure p [MPa]"), std::string::npos) << text;
  EXPECT_NE(text.find("x [µm]"), std::string::npos) << text;
  EXPECT_EQ(text.find("set terminal svg"), std::string::npos);  // no svg asked
}

TEST(ScaledUnit, PrefixesReadOneToAThousand) {
  EXPECT_EQ(scaled_unit(3e-9, "m").label, "nm");
  EXPECT_EQ(scaled_unit(2e-4, "m").label, "µm");
  EXPECT_EQ(scaled_unit(5e9, "Pa").label, "GPa");
  EXPECT_EQ(scaled_unit(0.5, "Pa").label, "Pa");  // no mPa
  EXPECT_EQ(scaled_unit(0, "m").label, "pm");     // the smallest prefix for an all-zero gap
  EXPECT_EQ(scaled_unit(2, "1").label, "1");
}

TEST_F(FieldPictures, PlotDrawsAWellFormedPngAndSvg) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (CI installs gnuplot-nox)";
  write_field(folder_ / "p.txt", small_pressure());
  const auto result = run("plot " + (folder_ / "p.txt").string());
  ASSERT_EQ(result.status, 0) << result.err;
  const auto [width, height] = png_size(folder_ / "p.png");
  // The terminal size the script asks for (app/field_picture.cpp: 900 wide, 700 * ly/lx + 120 high).
  EXPECT_EQ(width, 900u);
  EXPECT_EQ(height, static_cast<std::uint32_t>(700 * (40.0 / 60.0) + 120));
  const std::string svg = slurp(folder_ / "p.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_NE(svg.find("pressure p [MPa]"), std::string::npos);
  // One picture by its extension; any other is refused naming the option.
  ASSERT_EQ(run("plot " + (folder_ / "p.txt").string() + " --out " + (folder_ / "one.svg").string()).status,
            0);
  EXPECT_TRUE(std::filesystem::exists(folder_ / "one.svg"));
  EXPECT_FALSE(std::filesystem::exists(folder_ / "one.png"));
  const auto refused = run("plot " + (folder_ / "p.txt").string() + " --out " + (folder_ / "x.jpg").string());
  EXPECT_NE(refused.status, 0);
  EXPECT_NE(refused.err.find("--out"), std::string::npos) << refused.err;
}

TEST_F(FieldPictures, PlotDrawsASurfaceFileAsHeights) {
  if (!gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed (CI installs gnuplot-nox)";
  ASSERT_EQ(run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 32 --seed 3 --out " +
                (folder_ / "s.npy").string())
                .status,
            0);
  const auto result =
      run("plot " + (folder_ / "s.npy").string() + " --size 200e-6 --out " + (folder_ / "s.png").string());
  ASSERT_EQ(result.status, 0) << result.err;
  EXPECT_GT(png_size(folder_ / "s.png")[0], 0u);
  // No work file left beside it.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder_))
    ++files;
  EXPECT_EQ(files, 4u);  // s.npy, s.png, stdout.txt, stderr.txt
}

TEST_F(FieldPictures, SceneFieldsLandInTheOutputFolderWithMaps) {
  const auto scene =
      write("fields.toml", "name = \"fields\"\nreference = \"bem\"\n" + kSmallSurfaceAndMaterial +
                               "[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\nfields = "
                               "\"maps/surface\"\n");
  const auto out = folder_ / "out";
  const auto result = run("run " + scene.string() + " --no-plots --quiet --out " + out.string());
  ASSERT_EQ(result.status, 0) << result.err;
  for (const char* quantity : {"pressure", "gap", "contact"}) {
    const auto text = out / "maps" / (std::string("surface_load2_") + quantity + ".txt");
    EXPECT_TRUE(std::filesystem::exists(text)) << text;
    if (gnuplot_available()) {
      EXPECT_GT(png_size(text.string().substr(0, text.string().size() - 4) + ".png")[0], 0u);
    }
  }
  EXPECT_FALSE(std::filesystem::exists(folder_ / "maps"));  // not beside the scene file
  // No work folder left beside the output.
  for (const auto& entry : std::filesystem::directory_iterator(folder_))
    EXPECT_EQ(entry.path().filename().string().find(".out.fields"), std::string::npos) << entry.path();
  // The contact set is where the pressure is > 0 (the solver's definition), as classes 0 and 1.
  const Field pressure = read_field(out / "maps" / "surface_load2_pressure.txt");
  const Field contact = read_field(out / "maps" / "surface_load2_contact.txt");
  EXPECT_EQ(contact.unit, "1");
  EXPECT_TRUE(((pressure.values.heights() > 0).cast<Real>() == contact.values.heights()).all());
}

// With adhesion the contact set has a third class, the attracted zone out of contact (a > 0, p = 0), and the
// attraction is written as a field of its own; the net traction is p - a.
TEST_F(FieldPictures, AdhesiveFieldsShowTheAttractiveZone) {
  const auto surface = folder_ / "s.txt";
  ASSERT_EQ(run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 32 --seed 4 --out " +
                surface.string())
                .status,
            0);
  const auto result =
      run("bem " + surface.string() + " --loads 0.001 --modulus 4e6 --out " + (folder_ / "b.csv").string() +
          " --adhesion dugdale,work=0.05,stress=1e5 --fields " + (folder_ / "f").string());
  ASSERT_EQ(result.status, 0) << result.err;
  const Field pressure = read_field(folder_ / "f_load1_pressure.txt");
  const Field attraction = read_field(folder_ / "f_load1_attraction.txt");
  const Field contact = read_field(folder_ / "f_load1_contact.txt");
  EXPECT_EQ(attraction.unit, "Pa");
  const HeightMap& p = pressure.values.heights();
  const HeightMap& a = attraction.values.heights();
  const HeightMap& c = contact.values.heights();
  // Dugdale: the attraction is 0 or sigma0 = 1e5 Pa (to the rounding of p - t, 1e-6 relative of the
  // pressures around it).
  EXPECT_TRUE((a.abs() < 1e-1 || (a - 1e5).abs() < 1e-1).all());
  EXPECT_TRUE(((p > 0).cast<Real>() == (c == 1).cast<Real>()).all());            // contact
  EXPECT_TRUE(((p <= 0 && a > 0).cast<Real>() == (c == 2).cast<Real>()).all());  // attracted
  EXPECT_GT((c == 2).count(), 0);  // this load has an attractive zone
  if (gnuplot_available()) {
    EXPECT_GT(png_size(folder_ / "f_load1_attraction.png")[0], 0u);
  }
}

TEST_F(FieldPictures, SceneFieldsOutsideTheOutputFolderAreRefused) {
  for (const char* prefix : {"../f", "/tmp/f"}) {
    const auto scene =
        write("bad.toml", "name = \"bad\"\nreference = \"bem\"\n" + kSmallSurfaceAndMaterial +
                              "[loads]\nvalues = [1e-3]\n[methods.bem]\nfields = \"" + prefix + "\"\n");
    const auto result =
        run("run " + scene.string() + " --no-plots --quiet --out " + (folder_ / "o").string());
    EXPECT_NE(result.status, 0) << prefix;
    EXPECT_NE(result.err.find("methods.bem.fields"), std::string::npos) << result.err;
    EXPECT_NE(result.err.find("output folder"), std::string::npos) << result.err;
  }
}

TEST(ProgressLine, ShortWithLoadCountAndPercentage) {
  const std::string line = progress_line({.stage = stage_label("bem (active_set, periodic, tolerance 1e-08, "
                                                               "again on twice the points a side)") +
                                                   " 256 x 256",
                                          .load = 3,
                                          .loads = 12,
                                          .load_value = 0.005,
                                          .iterations = 142,
                                          .seconds = 1.2345,
                                          .stage_seconds = 4});
  EXPECT_EQ(line, "bem 256 x 256: load 3/12 (25 %), P/(E* A0) = 0.005, 142 iterations in 1.23 s");
  EXPECT_EQ(stage_done_line("sweep (exact levels, 4-connected, periodic)", 12.345), "sweep: done in 12.3 s");
  EXPECT_EQ(stage_label("surface"), "surface");
}

TEST_F(FieldPictures, ProgressOnlyWhenAskedOffTheTerminal) {
  const auto scene = write("p.toml", "name = \"p\"\nreference = \"bem\"\n" + kSmallSurfaceAndMaterial +
                                         "[loads]\nvalues = [1e-3, 1e-2]\n[methods.bem]\n");
  // stderr is a file here: silent by default.
  const auto quiet = run("run " + scene.string() + " --no-plots --out " + (folder_ / "a").string());
  ASSERT_EQ(quiet.status, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  const auto told = run("run " + scene.string() + " --no-plots --progress --out " + (folder_ / "b").string());
  ASSERT_EQ(told.status, 0) << told.err;
  EXPECT_NE(told.err.find("contactbench run: bem 32 x 32: load 2/2 (100 %), P/(E* A0) = 0.01, "),
            std::string::npos)
      << told.err;
  std::istringstream lines(told.err);
  for (std::string line; std::getline(lines, line);)
    EXPECT_LE(line.size(), 100u) << line;  // one short line each (the issue: 222 characters before)
}

// The load-area script from a report made by hand: a reference with an error estimate, a method that stops.
TEST(LoadAreaPlot, BandErrorPanelBoundedAxesAndWhereAMethodStops) {
  SceneReport report;
  report.scene.name = "plot";
  report.scene.reference = "bem";
  report.scene.loads = {1e-3, 1e-2, 2e-2};
  MethodResult bem;
  bem.label = "bem";
  bem.curve.area_fraction = {0.01, 0.08, 0.15};
  bem.curve.area_fraction_error = {1e-4, 2e-4, 3e-4};
  MethodResult theory;
  theory.label = "stops_early";
  theory.curve.area_fraction = {0.02, 0.1, std::nan("")};
  report.methods = {bem, theory};
  std::ostringstream script;
  write_gnuplot_script(script, report, "a.png", "a.svg");
  const std::string text = script.str();
  // The band [A - error, A + error] from the reference's data block, and the relative error A/A_ref - 1.
  EXPECT_NE(text.find("$method0 using 1:3:4 with filledcurves"), std::string::npos) << text;
  EXPECT_NE(text.find("$method1 using 1:5 with linespoints"), std::string::npos) << text;
  // The first row of each block: load, A, A - error, A + error, A/A_ref - 1, error_ref/A_ref (NaN: none).
  // Written as the shortest decimals that read back to the same doubles: compared to 1e-15 relative (a few
  // roundings of the subtraction and division).
  const auto first_row = [&](const std::string& block) {
    std::istringstream rows(text.substr(text.find(block + " << EOD\n") + block.size() + 8));
    std::vector<double> values;
    for (int column = 0; column < 6; ++column) {
      std::string cell;
      rows >> cell;
      values.push_back(cell == "NaN" ? std::nan("") : std::stod(cell));
    }
    return values;
  };
  const std::vector<double> reference = first_row("$method0"), stops = first_row("$method1");
  const std::vector<double> expected_reference{1e-3, 0.01, 0.0099, 0.0101, 0, 0.01};
  for (std::size_t c = 0; c < 6; ++c)
    EXPECT_NEAR(reference[c], expected_reference[c], 1e-15) << "column " << c + 1;
  EXPECT_NEAR(stops[1], 0.02, 1e-15);
  EXPECT_TRUE(std::isnan(stops[2]) && std::isnan(stops[3]));  // no error estimate of its own
  EXPECT_NEAR(stops[4], 1.0, 1e-15);                          // 0.02 / 0.01 - 1
  EXPECT_NEAR(stops[5], 0.01, 1e-15);                         // the reference's 1e-4 / 0.01
  // Log axes a tenth of a decade (factor 1.26) beyond the data: loads 1e-3 ... 2e-2, areas 0.01 ... 0.15.
  const std::regex log_range(
      R"(set title '\(b\) logarithmic axes'\nset xrange \[([^:]+):([^\]]+)\]\nset yrange \[([^:]+):([^\]]+)\])");
  std::smatch range;
  ASSERT_TRUE(std::regex_search(text, range, log_range)) << text;
  EXPECT_NEAR(std::stod(range[1]), 1e-3 / 1.26, 1e-17);  // shortest round trip: exact to the last bit
  EXPECT_NEAR(std::stod(range[2]), 2e-2 * 1.26, 1e-16);
  EXPECT_NEAR(std::stod(range[3]), 0.01 / 1.26, 1e-17);
  EXPECT_NEAR(std::stod(range[4]), 0.15 * 1.26, 1e-16);
  // Where a method stops, in its legend entry; the legend is a panel of its own (no key on the data panels).
  EXPECT_NE(text.find("title \"stops_early\\n    no value above P/(E* A0) = 0.01\" noenhanced"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("set key off"), std::string::npos);
  EXPECT_NE(text.find("{/:Italic P} / ({/:Italic E}^*{/:Italic A}_0)"), std::string::npos);  // typeset label
}

}  // namespace
}  // namespace contactbench
