// FFTW wisdom kept between runs (core/fftw_wisdom.hpp, app/fftw_wisdom_file.hpp): what a file carries is the
// plans themselves (a convolution planned from it is bit-identical), a bad file is refused without changing
// FFTW's wisdom, the file is written whole or not at all, and the commands warn about bad files, keep none
// with `none` and never replace a file that is not theirs. Every test here names its wisdom file or switches
// it off: none writes into the user's cache (ctest also sets CONTACTBENCH_FFTW_WISDOM=none for every test).
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <fftw3.h>

#include "cli_runner.hpp"
#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/fftw_wisdom.hpp"
#include "contactbench/core/generation.hpp"
#include "csv_rows.hpp"

namespace contactbench {
namespace {

using testing::CommandResult;
using testing::slurp;

class FftwWisdom : public testing::CliTest {
 protected:
  FftwWisdom() : CliTest("contactbench_wisdom_") { forget_fftw_wisdom(); }
};

// Whether FFTW's wisdom holds a measured plan of the 2D real-to-complex transform of ny x nx on one thread,
// in each precision: FFTW_WISDOM_ONLY makes a plan only from wisdom, never by planning. The CSV's answers:
// its lines that are not comments (which hold the date), without the last column, the solve's wall time.
std::string data_lines(const std::string& csv) {
  std::istringstream lines(csv);
  std::string line, data;
  while (std::getline(lines, line))
    if (!line.empty() && line[0] != '#') data += line.substr(0, line.rfind(',')) + "\n";
  return data;
}

template <class T>
bool has_measured_r2c(int nx, int ny) {
  auto lock = lock_fftw_planner();
  const std::size_t real = static_cast<std::size_t>(nx * ny),
                    half = static_cast<std::size_t>(ny * (nx / 2 + 1));
  if constexpr (std::is_same_v<T, double>) {
    double* in = fftw_alloc_real(real);
    fftw_complex* out = fftw_alloc_complex(half);
    fftw_plan_with_nthreads(1);
    fftw_plan plan = fftw_plan_dft_r2c_2d(ny, nx, in, out, FFTW_MEASURE | FFTW_WISDOM_ONLY);
    const bool found = plan != nullptr;
    if (plan) fftw_destroy_plan(plan);
    fftw_free(in);
    fftw_free(out);
    return found;
  } else {
    float* in = fftwf_alloc_real(real);
    fftwf_complex* out = fftwf_alloc_complex(half);
    fftwf_plan_with_nthreads(1);
    fftwf_plan plan = fftwf_plan_dft_r2c_2d(ny, nx, in, out, FFTW_MEASURE | FFTW_WISDOM_ONLY);
    const bool found = plan != nullptr;
    if (plan) fftwf_destroy_plan(plan);
    fftwf_free(in);
    fftwf_free(out);
    return found;
  }
}

// Measures that plan (the arrays are scratch: MEASURE overwrites them).
template <class T>
void measure_r2c(int nx, int ny) {
  auto lock = lock_fftw_planner();
  const std::size_t real = static_cast<std::size_t>(nx * ny),
                    half = static_cast<std::size_t>(ny * (nx / 2 + 1));
  if constexpr (std::is_same_v<T, double>) {
    double* in = fftw_alloc_real(real);
    fftw_complex* out = fftw_alloc_complex(half);
    fftw_plan_with_nthreads(1);
    fftw_destroy_plan(fftw_plan_dft_r2c_2d(ny, nx, in, out, FFTW_MEASURE));
    fftw_free(in);
    fftw_free(out);
  } else {
    float* in = fftwf_alloc_real(real);
    fftwf_complex* out = fftwf_alloc_complex(half);
    fftwf_plan_with_nthreads(1);
    fftwf_destroy_plan(fftwf_plan_dft_r2c_2d(ny, nx, in, out, FFTW_MEASURE));
    fftwf_free(in);
    fftwf_free(out);
  }
}

TEST_F(FftwWisdom, AFileCarriesMeasuredPlansOfBothPrecisions) {
  const std::string key = fftw_wisdom_key(1);
  const auto file = folder_ / "wisdom.txt";
  measure_r2c<double>(48, 40);
  measure_r2c<float>(40, 48);
  ASSERT_TRUE(has_measured_r2c<double>(48, 40));  // the probe sees what was measured
  export_fftw_wisdom(file, key);
  forget_fftw_wisdom();
  ASSERT_FALSE(has_measured_r2c<double>(48, 40));  // and nothing once forgotten
  ASSERT_FALSE(has_measured_r2c<float>(40, 48));
  const WisdomImport read = import_fftw_wisdom(file, key);
  EXPECT_TRUE(read.found && read.wisdom_file && read.imported) << read.problem;
  EXPECT_TRUE(read.problem.empty()) << read.problem;
  EXPECT_TRUE(has_measured_r2c<double>(48, 40));
  EXPECT_TRUE(has_measured_r2c<float>(40, 48));
  EXPECT_FALSE(has_measured_r2c<double>(40, 48));  // only what was measured: the shapes are not mixed up
}

// A convolution of a fixed input through a measured plan on a lattice large enough to be measured
// (kMinPointsForThreads points), before and after its wisdom went through a file.
template <class T>
std::vector<T> convolve_measured(Index n) {
  Convolution<T> convolution(n, n, false, 1, FftRigor::measure);
  Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> multiplier(n, n / 2 + 1);
  for (Index ky = 0; ky < n; ++ky)
    for (Index kx = 0; kx <= n / 2; ++kx)
      multiplier(ky, kx) = 1.0 / (1.0 + static_cast<double>(std::min(ky, n - ky) + kx));  // even in ky
  convolution.set_multiplier(multiplier);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<T> in(static_cast<std::size_t>(n * n)), out(in.size());
  for (T& v : in)
    v = static_cast<T>(uniform(random));
  convolution.apply(in.data(), out.data());
  return out;
}

template <class T>
void expect_bit_identical_after_a_round_trip(const std::filesystem::path& file) {
  constexpr Index n = 256;  // 256^2 = kMinPointsForThreads: the smallest lattice planned by measuring
  static_assert(n * n >= kMinPointsForThreads);
  const std::vector<T> before = convolve_measured<T>(n);
  export_fftw_wisdom(file, fftw_wisdom_key(1));
  forget_fftw_wisdom();
  ASSERT_TRUE(import_fftw_wisdom(file, fftw_wisdom_key(1)).imported);
  const std::vector<T> after = convolve_measured<T>(n);
  // Tolerance zero: the same plans do the same arithmetic on the same input, to the last bit. (Plans chosen
  // by measuring again could differ and round differently; the imported ones are the ones measured before.)
  ASSERT_EQ(before.size(), after.size());
  EXPECT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(T)), 0);
}

TEST_F(FftwWisdom, AConvolutionPlannedFromImportedWisdomIsBitIdentical) {
  expect_bit_identical_after_a_round_trip<double>(folder_ / "double.txt");
  expect_bit_identical_after_a_round_trip<float>(folder_ / "float.txt");
}

TEST_F(FftwWisdom, BadFilesAreRefusedWithTheirReasonAndChangeNothing) {
  const std::string key = fftw_wisdom_key(2);
  measure_r2c<double>(36, 30);
  const auto good = folder_ / "good.txt";
  export_fftw_wisdom(good, key);
  const std::string text = slurp(good);
  forget_fftw_wisdom();
  measure_r2c<float>(30, 36);  // what FFTW knows before each bad file: it must still know it after

  const WisdomImport missing = import_fftw_wisdom(folder_ / "absent.txt", key);
  EXPECT_FALSE(missing.found);
  EXPECT_TRUE(missing.problem.empty()) << missing.problem;  // no file yet is no problem

  const WisdomImport foreign = import_fftw_wisdom(good, fftw_wisdom_key(3));
  EXPECT_TRUE(foreign.wisdom_file);
  EXPECT_FALSE(foreign.imported);
  EXPECT_NE(foreign.problem.find("foreign"), std::string::npos) << foreign.problem;

  const WisdomImport alien = import_fftw_wisdom(write("alien.txt", "0 0 1.5e-7\n0 1 1.6e-7\n"), key);
  EXPECT_TRUE(alien.found);
  EXPECT_FALSE(alien.wisdom_file);
  EXPECT_NE(alien.problem.find("not a contactbench FFTW wisdom file"), std::string::npos) << alien.problem;

  // Cut anywhere after the header (a file half-written by something else, a damaged disk), or garbled.
  const std::string header = text.substr(0, text.find('\n') + 1);
  for (const std::string& damaged : {text.substr(0, text.size() / 2), text.substr(0, text.size() - 3), header,
                                     header + "[fftw double]\n(garbage)\n[fftw float]\n(garbage)\n"}) {
    const WisdomImport read = import_fftw_wisdom(write("damaged.txt", damaged), key);
    EXPECT_TRUE(read.wisdom_file);
    EXPECT_FALSE(read.imported) << damaged;
    EXPECT_NE(read.problem.find("damaged"), std::string::npos) << read.problem;
  }
  EXPECT_FALSE(has_measured_r2c<double>(36, 30));  // nothing of the damaged copies was taken
  EXPECT_TRUE(has_measured_r2c<float>(30, 36));    // and nothing known was lost
}

TEST_F(FftwWisdom, TheFileIsWrittenWholeOrNotAtAll) {
  const std::string key = fftw_wisdom_key(1);
  measure_r2c<double>(24, 20);
  const auto file = folder_ / "wisdom.txt";
  export_fftw_wisdom(file, key);
  // Written by renaming a finished temporary: no temporary is left beside it, and it reads back whole.
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder_))
    names.push_back(entry.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"wisdom.txt"});
  EXPECT_TRUE(import_fftw_wisdom(file, key).imported);
  // A path that cannot be replaced by a file (here a symbolic link) is refused before anything is written;
  // what the link points to keeps its bytes.
  const auto target = write("target.txt", "kept\n");
  std::filesystem::create_symlink(target, folder_ / "link.txt");
  EXPECT_THROW(export_fftw_wisdom(folder_ / "link.txt", key), Error);
  EXPECT_EQ(slurp(target), "kept\n");
}

TEST_F(FftwWisdom, GeneratedSurfacesDoNotDependOnTheWisdomHeld) {
  // The generator promises the same bits on any thread count (core/fft.hpp, ReproducibleInverseFft2d), and a
  // run now holds measured wisdom before it generates its surface: wisdom of other transforms must not reach
  // the generator's estimated plans (or their sub-plans). Compared bit for bit: tolerance zero.
  const Grid grid{256, 256, 200e-6, 200e-6, true};
  SelfAffinePsd psd;
  psd.sigma = 0.5e-6;
  psd.hurst = 0.5;
  psd.qr = 3.14e4;
  const Surface before = generate_surface(grid, psd, 3, 2);
  const Surface refined_before = refine(before, 512, 512, 2);
  for (const Index n : {256, 512}) {
    convolve_measured<double>(n);
    Convolution<double> padded(n / 2, n / 2, true, 1, FftRigor::measure);
  }
  const Surface after = generate_surface(grid, psd, 3, 2);
  const Surface refined_after = refine(after, 512, 512, 2);
  EXPECT_TRUE((before.heights() == after.heights()).all());
  EXPECT_TRUE((refined_before.heights() == refined_after.heights()).all());
}

// The commands: a 256 x 256 periodic surface, one load (its operators are estimated since the planner level
// is chosen by the work, docs/solvers.md Planning; the run still measures and keeps other plans).
class FftwWisdomCommands : public FftwWisdom {
 protected:
  void SetUp() override {
    const CommandResult made =
        run("generate --sigma 0.5e-6 --hurst 0.5 --qr 3.14e4 --size 200e-6 --grid 256 "
            "--seed 3 --out " +
            surface_.string());
    ASSERT_EQ(made.status, 0) << made.err;
  }
  CommandResult bem(const std::string& flags, const std::string& environment, int threads = 1) {
    return run("bem " + surface_.string() + " --periodic --loads 0.01 --threads " + std::to_string(threads) +
                   " " + flags,
               environment);
  }
  // XDG_CACHE_HOME points into the test's folder, so that the default file would land there, not in the
  // user's.
  std::string environment(const std::string& wisdom) const {
    return "XDG_CACHE_HOME=" + cache_.string() + " CONTACTBENCH_FFTW_WISDOM=" + wisdom;
  }
  std::filesystem::path surface_ = folder_ / "surface.txt", cache_ = folder_ / "cache";
};

TEST_F(FftwWisdomCommands, BemKeepsWisdomInTheCacheFolderAndAnswersAsBefore) {
  // CONTACTBENCH_FFTW_WISDOM empty: the default file of this key in $XDG_CACHE_HOME/contactbench/.
  const CommandResult cold = bem("", environment(""));
  ASSERT_EQ(cold.status, 0) << cold.err;
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(cache_ / "contactbench"))
    files.push_back(entry.path());
  ASSERT_EQ(files.size(), 1u);
  EXPECT_NE(files[0].filename().string().find("threads"), std::string::npos) << files[0];
  EXPECT_TRUE(import_fftw_wisdom(files[0], fftw_wisdom_key(1)).imported);
  const std::string written = slurp(files[0]);
  // Planned from the file: the measured plans of the first run, so the same numbers to the last digit.
  const CommandResult warm = bem("", environment(""));
  ASSERT_EQ(warm.status, 0) << warm.err;
  EXPECT_EQ(warm.err.find("warning"), std::string::npos) << warm.err;
  EXPECT_FALSE(data_lines(cold.out).empty());
  EXPECT_EQ(data_lines(warm.out), data_lines(cold.out));
  EXPECT_EQ(slurp(files[0]), written);  // nothing new was planned, so nothing was written
}

TEST_F(FftwWisdomCommands, NoneKeepsNoFile) {
  const CommandResult off = bem("", environment("none"));
  ASSERT_EQ(off.status, 0) << off.err;
  const auto chosen = folder_ / "chosen.txt";
  const CommandResult flag_off = bem("--fftw-wisdom none", environment(chosen.string()));
  ASSERT_EQ(flag_off.status, 0) << flag_off.err;
  EXPECT_FALSE(std::filesystem::exists(cache_));
  EXPECT_FALSE(std::filesystem::exists(chosen));
  // The flag wins over the variable, and names any file.
  const CommandResult flag = bem("--fftw-wisdom " + chosen.string(), environment("none"));
  ASSERT_EQ(flag.status, 0) << flag.err;
  EXPECT_TRUE(import_fftw_wisdom(chosen, fftw_wisdom_key(1)).imported);
  EXPECT_FALSE(std::filesystem::exists(cache_));
}

TEST_F(FftwWisdomCommands, BadFilesAreWarnedByNameAndNeverStopTheRun) {
  const CommandResult reference = bem("", environment("none"));
  ASSERT_EQ(reference.status, 0) << reference.err;
  // Damaged: warned, planned anew, rewritten whole.
  const auto damaged =
      write("damaged.txt", "contactbench FFTW wisdom for " + fftw_wisdom_key(1) + "\n(garbage\n");
  const CommandResult repaired = bem("", environment(damaged.string()));
  ASSERT_EQ(repaired.status, 0) << repaired.err;
  EXPECT_NE(repaired.err.find("warning: FFTW wisdom file " + damaged.string() + " is damaged"),
            std::string::npos)
      << repaired.err;
  EXPECT_TRUE(import_fftw_wisdom(damaged, fftw_wisdom_key(1)).imported);
  // Made for another thread count: foreign, replaced.
  const CommandResult foreign = bem("", environment(damaged.string()), 2);
  ASSERT_EQ(foreign.status, 0) << foreign.err;
  EXPECT_NE(foreign.err.find("foreign"), std::string::npos) << foreign.err;
  EXPECT_TRUE(import_fftw_wisdom(damaged, fftw_wisdom_key(2)).imported);
  // Not a wisdom file (a surface given by mistake): warned, and left as it was.
  const std::string heights = slurp(surface_);
  const CommandResult alien = bem("--fftw-wisdom " + surface_.string(), environment("none"));
  ASSERT_EQ(alien.status, 0) << alien.err;
  EXPECT_NE(alien.err.find(surface_.string() + " is not a contactbench FFTW wisdom file"), std::string::npos)
      << alien.err;
  EXPECT_NE(alien.err.find("left untouched"), std::string::npos) << alien.err;
  EXPECT_EQ(slurp(surface_), heights);
  // A folder that cannot be made (its parent is a file): warned with the file's name, the answer written.
  const auto unwritable = folder_ / "surface.txt" / "wisdom.txt";
  const CommandResult lost = bem("", environment(unwritable.string()));
  ASSERT_EQ(lost.status, 0) << lost.err;
  EXPECT_NE(lost.err.find("FFTW wisdom file " + unwritable.string() + " not written"), std::string::npos)
      << lost.err;
  // Both runs planned by measuring, each choosing its plans by timing: the same answer up to the round-off of
  // possibly different FFT algorithms (seen: 2e-15 relative in the separation), so 1e-12 relative.
  std::vector<std::string> header;
  const std::vector<CsvRow> answer = csv_rows(lost.out, header), expected = csv_rows(reference.out, header);
  ASSERT_EQ(answer.size(), 1u);
  ASSERT_EQ(expected.size(), 1u);
  EXPECT_EQ(answer[0].at("converged"), "1");
  const double separation = std::stod(answer[0].at("separation"));
  EXPECT_NEAR(separation, std::stod(expected[0].at("separation")), 1e-12 * separation);
}

TEST_F(FftwWisdomCommands, RunListsPlanningAmongItsStages) {
  const auto scene = write("scene.toml", "name = \"planning\"\n[surface]\nfile = \"" + surface_.string() +
                                             "\"\n[material]\nE = 100e9\nnu = 0.3\n[loads]\nvalues = [0.01]\n"
                                             "[methods.bem]\nmethod = \"bem\"\n");
  const CommandResult ran =
      run("run " + scene.string() + " --threads 1 --no-plots --quiet --out " + (folder_ / "out").string(),
          environment((folder_ / "w.txt").string()));
  ASSERT_EQ(ran.status, 0) << ran.err;
  const std::string table = slurp(folder_ / "out" / "table.md");
  EXPECT_NE(table.find("fftw planning (included in the stages above; no wisdom read) "), std::string::npos)
      << table;
  const CommandResult again =
      run("run " + scene.string() + " --threads 1 --no-plots --quiet --out " + (folder_ / "out").string(),
          environment((folder_ / "w.txt").string()));
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(slurp(folder_ / "out" / "table.md")
                .find("fftw planning (included in the stages above; wisdom read from its file) "),
            std::string::npos);
}

}  // namespace
}  // namespace contactbench
