// The whole `contactbench bem` command against its solve alone, in one run, so that what the command adds
// (reading the text surface, planning, the statistics, writing the CSV) is a column (issue 42;
// docs/solvers.md, Planning). In-process: the command is run_cli (app/cli.hpp), as main() calls it, on a
// surface file written once by `contactbench generate` (the surface: sigma 0.5 um, H 0.5, qr 3.14e4
// /m, 200 um, seed 1); the process start (a few ms) is not in it. Its FFTW wisdom file is made by one untimed
// run first: the times are those of a machine's second run. The solve alone: BemSolver (the command's default
// solver and its tolerance 1e-8) made on the surface already read and solved at each load, its own planning
// from the same wisdom included. One load (0.000478 of E*, about 0.5 % contact) and a 12-load curve (0.000478
// to 0.05). All on kThreads threads.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

#include "bench_surfaces.hpp"
#include "contactbench/app/cli.hpp"
#include "contactbench/bem/bem_solver.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/topography_io.hpp"

namespace contactbench::bench {
namespace {

constexpr Real kModulus = 100e9 / (1 - 0.3 * 0.3);  // the command's default material: E = 100 GPa, nu = 0.3
const std::vector<std::string> kOneLoad = {"0.000478"};
const std::vector<std::string> kCurve = {"0.000478", "0.001", "0.0015", "0.002", "0.003", "0.004",
                                         "0.006",    "0.008", "0.012",  "0.018", "0.03",  "0.05"};

std::filesystem::path folder() {
  static const std::filesystem::path path = [] {
    auto p =
        std::filesystem::temp_directory_path() / ("contactbench_bench_command_" + std::to_string(getpid()));
    std::filesystem::create_directories(p);
    return p;
  }();
  return path;
}

int cli(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), "contactbench");
  std::vector<char*> argv;
  for (std::string& a : arguments)
    argv.push_back(a.data());
  return run_cli(static_cast<int>(argv.size()), argv.data());
}

// The surface file of n x n points, generated once.
std::filesystem::path surface_file(Index n) {
  const auto file = folder() / ("s" + std::to_string(n) + ".txt");
  if (!std::filesystem::exists(file) &&
      cli({"generate", "--sigma", "0.5e-6", "--hurst", "0.5", "--qr", "3.14e4", "--size", "200e-6", "--grid",
           std::to_string(n), "--seed", "1", "--out", file.string()}) != 0)
    throw Error("bench_command: generate failed");
  return file;
}

std::string joined(const std::vector<std::string>& loads) {
  std::string text;
  for (const std::string& l : loads)
    text += (text.empty() ? "" : ",") + l;
  return text;
}

std::vector<std::string> bem_arguments(Index n, const std::vector<std::string>& loads) {
  return {"bem",
          surface_file(n).string(),
          "--periodic",
          "--loads",
          joined(loads),
          "--threads",
          std::to_string(kThreads),
          "--fftw-wisdom",
          (folder() / "wisdom.txt").string(),
          "--out",
          (folder() / "out.csv").string()};
}

void whole_command(benchmark::State& state, Index n, const std::vector<std::string>& loads) {
  const auto arguments = bem_arguments(n, loads);
  if (cli(arguments) != 0) state.SkipWithError("the command failed");  // untimed: writes the wisdom
  for (auto _ : state)
    if (cli(arguments) != 0) state.SkipWithError("the command failed");
}

void solve_alone(benchmark::State& state, Index n, const std::vector<std::string>& loads) {
  if (cli(bem_arguments(n, loads)) != 0) state.SkipWithError("the command failed");  // the same wisdom
  const Surface surface = read_topography(surface_file(n)).with_periodic(true);
  BemSolverOptions options;
  options.tolerance = 1e-8;  // the command's default (app/methods/bem_settings.cpp)
  for (auto _ : state) {
    BemSolver solver(surface, kModulus, options, kThreads);
    for (const std::string& load : loads)
      benchmark::DoNotOptimize(solver.solve(std::stod(load) * kModulus).separation);
  }
}

void register_all() {
  for (const Index n : {512, 1024})
    for (const auto* loads : {&kOneLoad, &kCurve}) {
      const std::string tail = "/n:" + std::to_string(n) + "/loads:" + std::to_string(loads->size());
      benchmark::RegisterBenchmark(("command/whole" + tail).c_str(),
                                   [n, loads](benchmark::State& s) { whole_command(s, n, *loads); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
      benchmark::RegisterBenchmark(("command/solve" + tail).c_str(),
                                   [n, loads](benchmark::State& s) { solve_alone(s, n, *loads); })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(1);
    }
}

}  // namespace
}  // namespace contactbench::bench

int main(int argc, char** argv) {
  contactbench::bench::register_all();
  const int status = contactbench::bench::run_benchmarks(argc, argv, {});  // records the threads too
  std::filesystem::remove_all(contactbench::bench::folder());
  return status;
}
