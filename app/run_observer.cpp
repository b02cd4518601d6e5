#include "contactbench/app/run_observer.hpp"

#include <iostream>

#include <unistd.h>

#include "contactbench/app/mpi_launch.hpp"

#include <sstream>

namespace contactbench {

namespace {

// Seconds as a person reads them: 3 significant digits.
std::string seconds_text(double seconds) {
  std::ostringstream text;
  text.precision(3);
  text << seconds << " s";
  return text.str();
}

}  // namespace

std::string stage_label(const std::string& stage) {
  const std::size_t settings = stage.find(" (");
  return settings == std::string::npos ? stage : stage.substr(0, settings);
}

LoadProgress bem_load_progress(const std::string& stage, long long nx, long long ny, std::size_t k,
                               std::size_t loads, double load_value, long long iterations, double seconds,
                               double stage_seconds) {
  return {.stage = stage_label(stage) + " " + std::to_string(nx) + " x " + std::to_string(ny),
          .load = k + 1,
          .loads = loads,
          .load_value = load_value,
          .iterations = iterations,
          .seconds = seconds,
          .stage_seconds = stage_seconds};
}

std::string progress_line(const LoadProgress& load) {
  std::ostringstream line;
  const auto percent = load.loads == 0 ? 0 : (100 * load.load) / load.loads;
  line << load.stage << ": load " << load.load << "/" << load.loads << " (" << percent << " %), P/(E* A0) = ";
  line.precision(4);
  line << load.load_value << ", " << load.iterations << " iterations in " << seconds_text(load.seconds);
  return line.str();
}

RunObserver terminal_observer(const std::string& command, bool progress) {
  RunObserver observer;
  // Under mpiexec only rank 0 speaks, and its stderr is a pipe to the launcher, which prints it on the
  // launcher's terminal or log: it says what one process on a terminal says (docs/mpi.md).
  const bool terminal = ::isatty(STDERR_FILENO) != 0 || mpi_launch().ranks > 1;
  if (progress || terminal) {
    observer.stage_finished = [command, progress](const std::string& stage, double seconds) {
      if (progress || seconds > kProgressAfterSeconds)
        std::cerr << command << ": " << stage_done_line(stage, seconds) << '\n';
    };
    observer.load_solved = [command, progress](const LoadProgress& load) {
      if (progress || load.stage_seconds > kProgressAfterSeconds)
        std::cerr << command << ": " << progress_line(load) << '\n';
    };
  }
  observer.warning = [command](const std::string& text) {
    std::cerr << command << ": warning: " << text << '\n';
  };
  return observer;
}

std::string stage_done_line(const std::string& stage, double seconds) {
  return stage_label(stage) + ": done in " + seconds_text(seconds);
}

}  // namespace contactbench
