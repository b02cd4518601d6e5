// End to end through the contactbench binary: generate, stats, help, and errors a user would hit.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli_runner.hpp"
#include "csv_rows.hpp"

namespace contactbench {
namespace {

using testing::CommandResult;
using testing::slurp;

class Cli : public testing::CliTest {
 protected:
  Cli() : CliTest("contactbench_cli_") {}
};

// The number after "key": in a JSON text.
double json_value(const std::string& json, const std::string& key) {
  std::smatch match;
  if (!std::regex_search(json, match, std::regex("\"" + key + "\": ([-+0-9.eE]+)")))
    throw std::runtime_error("no numeric key " + key + " in " + json);
  return std::stod(match[1]);
}

const std::string kSurfaceA = "--sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 256 --seed 3";

TEST_F(Cli, RefusesToRunAsSeveralMpiRanksAndSaysWhy) {
  // As mpiexec -n 2 starts it (Open MPI's and PMI's variables): no stage is distributed yet (docs/mpi.md), so
  // every rank refuses rather than running the whole command twice; rank 0 says why and fails, the others
  // stay quiet and leave the job's status to it (a failing rank makes mpiexec kill rank 0, at times before it
  // has said why).
  const auto file = folder_ / "a.txt";
  for (const std::string environment :
       {"OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0", "PMI_SIZE=3 PMI_RANK=0"}) {
    const CommandResult refused = run("generate " + kSurfaceA + " --out " + file.string(), environment);
    EXPECT_EQ(refused.status, 1) << environment;
    EXPECT_NE(refused.err.find("MPI ranks"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("docs/mpi.md"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(file)) << environment;
  }
  const CommandResult quiet = run("generate " + kSurfaceA + " --out " + file.string(),
                                  "OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=1");
  EXPECT_EQ(quiet.status, 0);
  EXPECT_TRUE(quiet.err.empty()) << quiet.err;
  EXPECT_FALSE(std::filesystem::exists(file));  // it did nothing either
  // One rank is an ordinary run.
  const CommandResult single = run("generate " + kSurfaceA + " --out " + file.string(),
                                   "OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0");
  EXPECT_EQ(single.status, 0) << single.err;
  EXPECT_TRUE(std::filesystem::exists(file));
}

TEST_F(Cli, GeneratesSurfaceAAndItsStatsMatchTable2) {
  const auto file = folder_ / "a.txt";
  const CommandResult generated = run("generate " + kSurfaceA + " --out " + file.string());
  ASSERT_EQ(generated.status, 0) << generated.err;
  const CommandResult stats = run("stats " + file.string());
  ASSERT_EQ(stats.status, 0) << stats.err;
  for (const char* key :
       {"nx", "ny", "lx", "ly", "sq", "m0", "m2x", "m4x", "m2y", "m4y", "alpha", "rms_gradient"})
    EXPECT_NO_THROW(json_value(stats.out, key)) << key;
  EXPECT_NE(stats.out.find("\"periodic\": true"), std::string::npos);
  EXPECT_EQ(json_value(stats.out, "nx"), 256);
  // Table 2 to 1 % (as in the library's own test): m0 = 0.250 um^2, m2 = 0.0110, m4 = 0.0446 um^-2.
  EXPECT_NEAR(json_value(stats.out, "m0"), 0.250e-12, 0.01 * 0.250e-12);
  EXPECT_NEAR(json_value(stats.out, "m2x"), 0.0110, 0.01 * 0.0110);
  EXPECT_NEAR(json_value(stats.out, "m4y"), 0.0446e12, 0.01 * 0.0446e12);
}

TEST_F(Cli, GenerateWritesTheFormatItsExtensionNames) {
  // As convert does: .npy and .x3p are written in those formats, never the text format under their name (a
  // .npy file of text was refused on reading as a NumPy array). Each read back by stats gives the heights'
  // rms of the text file to the digits both print (all three hold the same doubles).
  const std::string surface =
      "generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 64 --out ";
  const auto text = folder_ / "a.txt";
  ASSERT_EQ(run(surface + text.string()).status, 0);
  const CommandResult reference = run("stats " + text.string());
  ASSERT_EQ(reference.status, 0) << reference.err;
  for (const char* name : {"a.npy", "a.x3p"}) {
    const auto file = folder_ / name;
    const CommandResult generated = run(surface + file.string());
    ASSERT_EQ(generated.status, 0) << generated.err;
    std::ifstream in(file, std::ios::binary);
    std::string start(6, '\0');
    in.read(start.data(), 6);
    EXPECT_EQ(start.rfind("# cont", 0), std::string::npos) << name << " holds the text format";
    const bool npy = file.extension() == ".npy";  // a NumPy array carries no lateral size
    const CommandResult stats = run("stats " + file.string() + (npy ? " --size 200e-6" : ""));
    ASSERT_EQ(stats.status, 0) << name << ": " << stats.err;
    EXPECT_DOUBLE_EQ(json_value(stats.out, "sq"), json_value(reference.out, "sq")) << name;
  }
}

TEST_F(Cli, RefineWritesTheSameRealisationOnAFinerGrid) {
  const auto coarse = folder_ / "coarse.txt", fine = folder_ / "fine.txt";
  ASSERT_EQ(run("generate " + kSurfaceA + " --out " + coarse.string()).status, 0);
  ASSERT_EQ(run("generate " + kSurfaceA + " --refine 512 --out " + fine.string()).status, 0);
  const CommandResult a = run("stats " + coarse.string()), b = run("stats " + fine.string());
  EXPECT_EQ(json_value(b.out, "nx"), 512);
  // Same coefficients, sampled finer: the moments agree to round-off (1e-10 relative, as the library test).
  EXPECT_NEAR(json_value(b.out, "m2x"), json_value(a.out, "m2x"), 1e-10 * json_value(a.out, "m2x"));
}

TEST_F(Cli, StatsOfAMeasuredFileWithItsOwnSizes) {
  const CommandResult stats = run(std::string("stats ") + CB_DATA_DIR + "/measured/matrix-4.txt");
  ASSERT_EQ(stats.status, 0) << stats.err;
  EXPECT_EQ(json_value(stats.out, "nx"), 75);
  EXPECT_EQ(json_value(stats.out, "ny"), 305);
  EXPECT_NE(stats.out.find("\"periodic\": false"), std::string::npos);
  EXPECT_NE(stats.out.find("\"window\": \"hann\""), std::string::npos);
}

// --version names the release and the commit built from: a 0.1.0-style version and a 12-digit commit (with
// "-dirty" when the tree had changes), or "unknown" when the sources were not a git checkout.
TEST_F(Cli, VersionNamesTheReleaseAndTheCommit) {
  const CommandResult version = run("--version");
  ASSERT_EQ(version.status, 0) << version.err;
  EXPECT_TRUE(std::regex_search(
      version.out,
      std::regex(R"(^contactbench [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{12}(-dirty)?|unknown)\)\n$)")))
      << version.out;
}

TEST_F(Cli, EveryCommandHasHelp) {
  for (const char* command : {"--help", "generate --help", "stats --help", "sweep --help", "bem --help"}) {
    const CommandResult help = run(command);
    EXPECT_EQ(help.status, 0) << command;
    EXPECT_NE(help.out.find("Usage"), std::string::npos) << command;
  }
}

TEST_F(Cli, AMissingFileFailsWithOneLineNamingIt) {
  const CommandResult stats = run("stats " + (folder_ / "nothing.txt").string());
  EXPECT_NE(stats.status, 0);
  EXPECT_NE(stats.err.find("nothing.txt"), std::string::npos) << stats.err;
  EXPECT_EQ(std::count(stats.err.begin(), stats.err.end(), '\n'), 1) << stats.err;
}

TEST_F(Cli, BadParametersFailNamingTheParameter) {
  const CommandResult negative =
      run("generate --sigma -1e-6 --hurst 0.5 --qr 3e4 --size 2e-4 --grid 64 --out " +
          (folder_ / "x.txt").string());
  EXPECT_NE(negative.status, 0);
  EXPECT_NE(negative.err.find("sigma"), std::string::npos) << negative.err;
  EXPECT_FALSE(std::filesystem::exists(folder_ / "x.txt"));
  const CommandResult missing = run("generate --hurst 0.5 --qr 3e4 --size 2e-4 --grid 64 --out x.txt");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("--sigma"), std::string::npos) << missing.err;
  const CommandResult unknown = run("frobnicate");
  EXPECT_NE(unknown.status, 0);
  const CommandResult plain = run("stats " + (folder_ / "plain.txt").string());
  EXPECT_NE(plain.status, 0);
}

// A seed is read as written: CLI11 alone would wrap -1 to 2^64 - 1 and clamp 2^64 to the same seed. A
// roll-off at or above the cut-off (here above Nyquist too) is refused, not generated as something else.
TEST_F(Cli, SeedsAndWavevectorsOutsideTheirRangeAreRefused) {
  const std::string base =
      "generate --sigma 1e-6 --hurst 0.8 --size 32e-6 --grid 16 --out " + (folder_ / "x.txt").string();
  for (const char* seed : {"-1", "18446744073709551616", "1.5", "abc"}) {
    const CommandResult bad = run(base + " --qr 2e5 --seed " + seed);
    EXPECT_NE(bad.status, 0) << seed;
    EXPECT_NE(bad.err.find("--seed"), std::string::npos) << bad.err;
  }
  EXPECT_EQ(run(base + " --qr 2e5 --seed 18446744073709551615").status, 0);
  // qs defaults to Nyquist, pi/dx = pi/2e-6 = 1.57e6 1/m.
  for (const char* wavevectors : {"--qr 1e6 --qs 1e6", "--qr 1.2e6 --qs 1e6", "--qr 2e7"}) {
    const CommandResult bad = run(base + " " + wavevectors);
    EXPECT_NE(bad.status, 0) << wavevectors;
    EXPECT_NE(bad.err.find("qr"), std::string::npos) << bad.err;
  }
}

// Inputs are regular files: a device is never read without end (stats /dev/zero used to grow until killed), a
// folder is named as one.
TEST_F(Cli, DevicesAndFoldersAreRefusedAsInputs) {
  for (const std::string command : {"stats", "run", "sweep"}) {
    const CommandResult device = run(command + " /dev/zero");
    EXPECT_NE(device.status, 0) << command;
    // Named either by the reader ("is a device, not a file") or by a scene's file key ("not a regular file").
    EXPECT_NE(device.err.find("/dev/zero"), std::string::npos) << command << ": " << device.err;
    EXPECT_TRUE(device.err.find("is a device") != std::string::npos ||
                device.err.find("not a regular file") != std::string::npos)
        << command << ": " << device.err;
    const CommandResult folder = run(command + " " + folder_.string());
    EXPECT_NE(folder.status, 0) << command;
    EXPECT_TRUE(folder.err.find("is a folder") != std::string::npos ||
                folder.err.find("not a regular file") != std::string::npos)
        << command << ": " << folder.err;
  }
}

// Requests that cannot fit in memory are refused from their parameters, before anything is allocated (each
// of these grew until the kernel killed it): the message gives the estimate and what the machine has.
TEST_F(Cli, OversizedRequestsAreRefusedWithTheirEstimate) {
  const auto surface = folder_ / "s.txt";
  ASSERT_EQ(run("generate --sigma 1e-6 --hurst 0.8 --qr 2e5 --size 32e-6 --grid 16 --out " + surface.string())
                .status,
            0);
  for (const std::string& command :
       {"sweep " + surface.string() + " --levels 1000000000",
        "generate --sigma 1e-6 --hurst 0.8 --qr 2e5 --size 32e-6 --grid 65536 --out " +
            (folder_ / "big.txt").string(),
        "generate --sigma 1e-6 --hurst 0.8 --qr 2e5 --size 32e-6 --grid 64 --refine 65536 --out " +
            (folder_ / "big.txt").string()}) {
    const CommandResult refused = run(command);
    EXPECT_NE(refused.status, 0) << command;
    EXPECT_NE(refused.err.find("needs about"), std::string::npos) << command << ": " << refused.err;
    EXPECT_NE(refused.err.find("available"), std::string::npos) << refused.err;
  }
  EXPECT_FALSE(std::filesystem::exists(folder_ / "big.txt"));
}

TEST_F(Cli, APlainMatrixNeedsItsSize) {
  const auto file = folder_ / "plain.txt";
  std::ofstream(file) << "1e-9 2e-9 3e-9\n4e-9 5e-9 6e-9\n";
  const CommandResult without = run("stats " + file.string());
  EXPECT_NE(without.status, 0);
  EXPECT_NE(without.err.find("plain.txt"), std::string::npos) << without.err;
  const CommandResult with = run("stats " + file.string() + " --size 3e-6 --periodic");
  ASSERT_EQ(with.status, 0) << with.err;
  EXPECT_EQ(json_value(with.out, "nx"), 3);
  EXPECT_DOUBLE_EQ(json_value(with.out, "ly"), 2e-6);  // square pixels by default
}

TEST_F(Cli, SweepWritesTheCurveAsCsv) {
  const auto surface = folder_ / "s.txt", csv = folder_ / "sweep.csv";
  ASSERT_EQ(run("generate --sigma 1e-6 --hurst 0.8 --qr 1e5 --size 100e-6 --grid 32 --seed 2 --out " +
                surface.string())
                .status,
            0);
  const CommandResult levels = run("sweep " + surface.string() + " --levels 10 --out " + csv.string());
  ASSERT_EQ(levels.status, 0) << levels.err;
  std::istringstream lines(slurp(csv));
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line.rfind("# contactbench sweep of ", 0), 0u) << line;
  EXPECT_NE(line.find("4-connectivity, periodic in x and y"), std::string::npos) << line;
  std::getline(lines, line);
  EXPECT_EQ(line, "z,area_fraction_nodes,spots");
  std::vector<double> area;
  while (std::getline(lines, line)) {
    std::istringstream fields(line);
    std::string z, a, spots;
    std::getline(fields, z, ',');
    std::getline(fields, a, ',');
    std::getline(fields, spots, ',');
    area.push_back(std::stod(a));
    if (area.size() == 1) {
      EXPECT_EQ(spots, "0");  // nothing lies above the highest point
    }
  }
  ASSERT_EQ(area.size(), 11u);  // 10 equal steps from the highest to the lowest height
  for (std::size_t j = 1; j < area.size(); ++j)
    EXPECT_GE(area[j], area[j - 1]) << j;
  EXPECT_LT(area.back(), 1.0);  // strictly above the lowest level: its own points are not counted

  const CommandResult exact = run("sweep " + surface.string() + " --connectivity 8");
  ASSERT_EQ(exact.status, 0) << exact.err;
  // One row per distinct height of the 32 x 32 random surface, plus the two header lines.
  EXPECT_EQ(std::count(exact.out.begin(), exact.out.end(), '\n'), 32 * 32 + 2);
}

// `sweep` is a front end over the scene pipeline: the same one-method scene through `run` writes the same
// level curve (<label>_levels.csv), row for row, and the same comment but for the command it names.
TEST_F(Cli, SweepAndRunOfTheSameSceneWriteTheSameLevels) {
  const auto surface = folder_ / "s.txt", scene = folder_ / "scene.toml", out = folder_ / "run";
  ASSERT_EQ(run("generate --sigma 1e-6 --hurst 0.8 --qr 1e5 --size 100e-6 --grid 32 --seed 5 --out " +
                surface.string())
                .status,
            0);
  std::ofstream(scene) << "name = \"levels\"\n[surface]\nfile = \"" << surface.string()
                       << "\"\n[material]\nestar = 1e11\n[loads]\nvalues = [1e-3, 1e-2]\n"
                          "[methods.plateau]\nwrite_levels = true\n[methods.coarse_8]\nmethod = \"plateau\"\n"
                          "levels = 10\nconnectivity = 8\nwrite_levels = true\n[methods.plateau_hertz]\n";
  const CommandResult scene_run =
      run("run " + scene.string() + " --out " + out.string() + " --no-plots --quiet");
  ASSERT_EQ(scene_run.status, 0) << scene_run.err;
  EXPECT_FALSE(std::filesystem::exists(out / "plateau_hertz_levels.csv"));  // not asked for
  for (const auto& [label, flags] :
       {std::pair<std::string, std::string>{"plateau", ""},
        std::pair<std::string, std::string>{"coarse_8", " --levels 10 --connectivity 8"}}) {
    const CommandResult sweep = run("sweep " + surface.string() + flags);
    ASSERT_EQ(sweep.status, 0) << sweep.err;
    const std::string levels = slurp(out / (label + "_levels.csv"));
    ASSERT_FALSE(levels.empty()) << label;
    // The rows (header line included) after one comment line each, which names the command.
    const std::size_t sweep_comment = sweep.out.find('\n'), run_comment = levels.find('\n');
    EXPECT_EQ(sweep.out.substr(sweep_comment), levels.substr(run_comment)) << label;
    EXPECT_GT(std::count(levels.begin(), levels.end(), '\n'), 12) << label;
    const std::string what = levels.substr(levels.find(": "), run_comment - levels.find(": "));
    EXPECT_EQ(sweep.out.substr(0, sweep_comment), "# contactbench sweep of " + surface.string() + what);
    EXPECT_EQ(levels.substr(0, run_comment), "# contactbench run of scene levels, " + label + what);
  }
}

TEST_F(Cli, SweepRefusesBadOptionsNamingThem) {
  const auto surface = folder_ / "s.txt";
  ASSERT_EQ(run("generate " + kSurfaceA + " --out " + surface.string()).status, 0);
  const CommandResult levels = run("sweep " + surface.string() + " --levels many");
  EXPECT_NE(levels.status, 0);
  EXPECT_NE(levels.err.find("--levels"), std::string::npos) << levels.err;
  EXPECT_NE(levels.err.find("exact"), std::string::npos) << levels.err;  // the accepted values are listed
  const CommandResult connectivity = run("sweep " + surface.string() + " --connectivity 6");
  EXPECT_NE(connectivity.status, 0);
  EXPECT_NE(connectivity.err.find("--connectivity"), std::string::npos) << connectivity.err;
}

TEST_F(Cli, BemWritesALoadAreaCurve) {
  const auto surface = folder_ / "s.txt", csv = folder_ / "bem.csv";
  ASSERT_EQ(run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 64 --seed 4 --out " +
                surface.string())
                .status,
            0);
  // Unordered on purpose: the loads are solved in increasing order.
  const CommandResult bem = run("bem " + surface.string() + " --loads 0.01,0.001 --out " + csv.string());
  ASSERT_EQ(bem.status, 0) << bem.err;
  std::vector<std::string> header;
  const std::vector<CsvRow> rows = csv_rows(slurp(csv), header);
  ASSERT_EQ(rows.size(), 2u);  // two loads
  for (const char* column : {"method", "area_fraction", "area_fraction_nodes", "area_fraction_corrected",
                             "separation", "spots", "iterations", "converged"})
    EXPECT_TRUE(rows[0].count(column)) << "no column " << column;
  const auto number = [&](std::size_t row, const char* column) { return std::stod(rows[row].at(column)); };
  EXPECT_LT(number(0, "load"), number(1, "load"));  // solved in increasing order
  for (std::size_t row : {0u, 1u}) {
    EXPECT_EQ(rows[row].at("converged"), "1");
    // The compared area is the corrected one, and the perimeter correction only removes area.
    EXPECT_EQ(rows[row].at("area_fraction"), rows[row].at("area_fraction_corrected"));
    EXPECT_LT(number(row, "area_fraction_corrected"), number(row, "area_fraction_nodes"));
  }
  EXPECT_LT(number(0, "area_fraction"), number(1, "area_fraction"));  // more load, more contact
}

// contactbench bem is a one-method scene: on the same file, with the same options, `bem` and `run` write the
// same columns and the same numbers (every digit; only the solver's wall time differs).
TEST_F(Cli, BemAndAOneMethodSceneGiveTheSameCurve) {
  const auto surface = folder_ / "s.txt", csv = folder_ / "bem.csv", scene = folder_ / "one.toml";
  ASSERT_EQ(run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 64 --seed 5 --out " +
                surface.string())
                .status,
            0);
  const CommandResult bem =
      run("bem " + surface.string() +
          " --loads 0.002,0.02 --tolerance 1e-9 --connectivity 8 --threads 1 --out " + csv.string());
  ASSERT_EQ(bem.status, 0) << bem.err;
  std::ofstream(scene) << "name = \"one\"\n[surface]\nfile = \"" << surface.string()
                       << "\"\n[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [0.002, 0.02]\n"
                          "[methods.bem]\ntolerance = 1e-9\nconnectivity = 8\n";
  const auto out = folder_ / "out";
  const CommandResult scene_run =
      run("run " + scene.string() + " --out " + out.string() + " --no-plots --quiet --threads 1");
  ASSERT_EQ(scene_run.status, 0) << scene_run.err;
  std::vector<std::string> bem_columns, run_columns;
  std::vector<CsvRow> from_bem = csv_rows(slurp(csv), bem_columns);
  std::vector<CsvRow> from_run = csv_rows(slurp(out / "curves.csv"), run_columns);
  EXPECT_EQ(bem_columns, run_columns);
  ASSERT_EQ(from_bem.size(), 2u);
  ASSERT_EQ(from_run.size(), 2u);
  for (auto* rows : {&from_bem, &from_run})
    for (CsvRow& row : *rows)
      row.erase("solve_seconds");  // wall time: the one column that may differ
  EXPECT_EQ(from_bem, from_run);
}

TEST_F(Cli, BemRefusesBadLoadsAndContradictoryFlags) {
  const auto surface = folder_ / "s.txt";
  ASSERT_EQ(run("generate " + kSurfaceA + " --out " + surface.string()).status, 0);
  const CommandResult negative = run("bem " + surface.string() + " --loads 0.01,-1");
  EXPECT_NE(negative.status, 0);
  EXPECT_NE(negative.err.find("--loads"), std::string::npos) << negative.err;
  const CommandResult both = run("bem " + surface.string() + " --loads 0.01 --periodic --non-periodic");
  EXPECT_NE(both.status, 0);
  EXPECT_NE(both.err.find("--non-periodic"), std::string::npos) << both.err;
  const CommandResult modulus = run("bem " + surface.string() + " --loads 0.01 --modulus -5");
  EXPECT_NE(modulus.status, 0);
  EXPECT_NE(modulus.err.find("--modulus"), std::string::npos) << modulus.err;
}

// --adhesion is the scene's interface.adhesion: the adhesive columns appear, the area at the same net load
// grows, and bad values are refused naming the flag's key (a table the scene reader checks, as for scenes).
TEST_F(Cli, BemAdhesionIsTheInterfacesAdhesion) {
  const auto surface = folder_ / "s.txt", plain = folder_ / "plain.csv", sticky = folder_ / "sticky.csv";
  ASSERT_EQ(run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 64 --seed 4 --out " +
                surface.string())
                .status,
            0);
  const std::string common = "bem " + surface.string() + " --loads 0.001 --modulus 4e6 --out ";
  ASSERT_EQ(run(common + plain.string()).status, 0);
  const CommandResult adhesive = run(common + sticky.string() + " --adhesion dugdale,work=0.05,stress=1e5");
  ASSERT_EQ(adhesive.status, 0) << adhesive.err;
  std::vector<std::string> header;
  const std::vector<CsvRow> without = csv_rows(slurp(plain), header);
  const std::vector<CsvRow> with = csv_rows(slurp(sticky), header);
  ASSERT_EQ(with.size(), 1u);
  for (const char* column : {"adhesive_load", "attractive_fraction", "zone_pixels", "outer_iterations"})
    EXPECT_TRUE(with[0].count(column)) << "no column " << column;
  EXPECT_GT(std::stod(with[0].at("area_fraction")), std::stod(without[0].at("area_fraction")));
  const CommandResult negative = run(common + sticky.string() + " --adhesion dugdale,work=-1,stress=1e5");
  EXPECT_NE(negative.status, 0);
  EXPECT_NE(negative.err.find("--adhesion work (interface.adhesion.work): out of range"), std::string::npos)
      << negative.err;
  const CommandResult missing = run(common + sticky.string() + " --adhesion exponential,work=0.05");
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.err.find("--adhesion range"), std::string::npos) << missing.err;
  const CommandResult not_a_number = run(common + sticky.string() + " --adhesion dugdale,work=x,stress=1");
  EXPECT_NE(not_a_number.status, 0);
  EXPECT_NE(not_a_number.err.find("is not a number"), std::string::npos) << not_a_number.err;
  // A solver that cannot take the law is refused naming the flag's key, before any solve (no file written).
  const auto refused_out = folder_ / "refused.csv";
  const CommandResult smooth =
      run("bem " + surface.string() + " --loads 0.001 --modulus 4e6 --out " + refused_out.string() +
          " --adhesion exponential,work=0.05,range=1e-6 --adhesive-solver constrained_cg");
  EXPECT_NE(smooth.status, 0);
  EXPECT_NE(smooth.err.find("adhesive_solver"), std::string::npos) << smooth.err;
  EXPECT_NE(smooth.err.find("exponential law has no such zone"), std::string::npos) << smooth.err;
  EXPECT_FALSE(std::filesystem::exists(refused_out));
}

// --approach-retract: the adhesive path instead of --loads (bem/adhesive_path.hpp): one row per state, down
// and back, the pull-off and the energy balance as comment lines; refused without --adhesion, with --loads,
// or with TO >= FROM, each naming what is wrong.
TEST_F(Cli, BemApproachRetractWritesThePath) {
  const auto surface = folder_ / "s.txt", path = folder_ / "path.csv";
  ASSERT_EQ(run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 32 --seed 4 --out " +
                surface.string())
                .status,
            0);
  const std::string common = "bem " + surface.string() + " --modulus 4e6 --out " + path.string();
  const CommandResult done =
      run(common + " --adhesion dugdale,work=0.05,stress=1e5 --approach-retract 2e-6,0.4e-6,2");
  ASSERT_EQ(done.status, 0) << done.err;
  const std::string text = slurp(path);
  EXPECT_NE(text.find("# pull_off_load = "), std::string::npos) << text;
  EXPECT_NE(text.find("# cycle work"), std::string::npos) << text;
  std::vector<std::string> header;
  const std::vector<CsvRow> rows = csv_rows(text, header);
  ASSERT_EQ(rows.size(), 5u);  // 2 steps down, 2 back, and the start
  EXPECT_EQ(rows.front().at("leg"), "approach");
  EXPECT_EQ(rows.back().at("leg"), "retract");
  EXPECT_GT(std::stod(rows[2].at("contact_fraction")), 0);
  const CommandResult plain = run(common + " --approach-retract 2e-6,0.4e-6,2");
  EXPECT_NE(plain.status, 0);
  EXPECT_NE(plain.err.find("needs --adhesion"), std::string::npos) << plain.err;
  const CommandResult both =
      run(common + " --adhesion dugdale,work=0.05,stress=1e5 --loads 0.01 --approach-retract 2e-6,0.4e-6,2");
  EXPECT_NE(both.status, 0);
  EXPECT_NE(both.err.find("--loads or --approach-retract"), std::string::npos) << both.err;
  const CommandResult upward =
      run(common + " --adhesion dugdale,work=0.05,stress=1e5 --approach-retract 0.4e-6,2e-6,4");
  EXPECT_NE(upward.status, 0);
  EXPECT_NE(upward.err.find("TO < FROM"), std::string::npos) << upward.err;
}

// A scene end to end through the binary: the files appear in --out, the table on standard output.
TEST_F(Cli, RunWritesTheComparisonOfASmallScene) {
  const auto scene = folder_ / "tiny.toml";
  std::ofstream(scene) << R"(name = "tiny"
[surface]
generate = { sigma = 0.5e-6, hurst = 0.5, qr = 3.14e4, size = 200e-6, grid = 32, seed = 1 }
[material]
E = 100e9
nu = 0.3
[loads]
values = [1e-3, 1e-2]
[methods.bem]
[methods.plateau]
[methods.persson]
)";
  const auto out = folder_ / "out";
  const CommandResult result =
      run("run " + scene.string() + " --out " + out.string() + " --no-plots --threads 1");
  ASSERT_EQ(result.status, 0) << result.err;
  for (const char* file : {"curves.csv", "summary.json", "table.md"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  EXPECT_FALSE(std::filesystem::exists(out / "load_area.png"));  // --no-plots
  EXPECT_NE(result.out.find("| plateau |"), std::string::npos) << result.out;
  // Nothing half-written is left behind: no temporary files in the folder (only the mark that a run wrote
  // it) and no staging folder beside it.
  for (const auto& entry : std::filesystem::directory_iterator(out))
    if (entry.path().filename() != ".contactbench-run") {
      EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
    }
  for (const auto& entry : std::filesystem::directory_iterator(folder_))
    EXPECT_EQ(entry.path().filename().string().rfind(".out.", 0), std::string::npos) << entry.path();
}

// A scene that names a missing file (and other problems) fails before any work: one error lists every
// problem with its key path, and no output folder is made.
TEST_F(Cli, RunRefusesABadSceneBeforeAnyWork) {
  const auto scene = folder_ / "bad.toml";
  std::ofstream(scene) << R"(name = "bad"
[surface]
file = "no_such_surface.txt"
[material]
E = -1
nu = 0.3
[loads]
values = [1e-3]
[methods.fem]
)";
  const auto out = folder_ / "out";
  const CommandResult result = run("run " + scene.string() + " --out " + out.string());
  EXPECT_EQ(result.status, 1);
  EXPECT_NE(result.err.find("no_such_surface.txt"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("material.E"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("methods.fem"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace contactbench
