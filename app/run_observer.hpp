// What a run tells the application while it works: stages as they start and finish, each solved load of a
// long stage, warnings (a solve that did not converge). The application owns where it goes (stderr for the
// command line, a record in tests); the libraries and the pipeline never write to a stream themselves.
#pragma once

#include <cstddef>
#include <functional>
#include <string>

namespace contactbench {

// One load of a stage solved: what a progress line says.
struct LoadProgress {
  std::string stage;         // the stage's short label (stage_label), e.g. "bem 256 x 256"
  std::size_t load = 0;      // 1-based, in the order solved
  std::size_t loads = 0;     // of the stage
  double load_value = 0;     // P/(E* A0)
  long long iterations = 0;  // of this load's solve
  double seconds = 0;        // of this load's solve
  double stage_seconds = 0;  // since the stage started
};

struct RunObserver {
  std::function<void(const std::string& stage)> stage_started;
  std::function<void(const std::string& stage, double seconds)> stage_finished;
  std::function<void(const LoadProgress& load)> load_solved;
  std::function<void(const std::string& text)> warning;  // one line, no newline

  void started(const std::string& stage) const {
    if (stage_started) stage_started(stage);
  }
  void finished(const std::string& stage, double seconds) const {
    if (stage_finished) stage_finished(stage, seconds);
  }
  void solved(const LoadProgress& load) const {
    if (load_solved) load_solved(load);
  }
  void warn(const std::string& text) const {
    if (warning) warning(text);
  }
};

// Without --progress, the terminal hears of a stage only once it has run this long (short runs say nothing).
inline constexpr double kProgressAfterSeconds = 2;

// A stage's name up to its settings in parentheses: "bem (active_set, periodic, ...)" -> "bem"; the whole
// name is in the report's "Stages that ran".
std::string stage_label(const std::string& stage);

// "bem 256 x 256: load 3/12 (25 %), P/(E* A0) = 0.005, 142 iterations in 1.3 s": one short line, no newline.
std::string progress_line(const LoadProgress& load);

// Load k (0-based) of `loads` of a BEM stage solved, on its nx x ny grid: the progress line's numbers (the
// stage's label "bem 256 x 256" from its full name). One process and MPI ranks say it the same way.
LoadProgress bem_load_progress(const std::string& stage, long long nx, long long ny, std::size_t k,
                               std::size_t loads, double load_value, long long iterations, double seconds,
                               double stage_seconds);

// "surface: done in 1.3 s".
std::string stage_done_line(const std::string& stage, double seconds);

// The observer of a command's run on stderr, one short line each, prefixed by the command ("contactbench
// run"): warnings always; with `progress` (--progress) every stage done and every load solved
// (progress_line above); without it the same only when stderr is a terminal and only for
// stages that have run longer than kProgressAfterSeconds; nothing when stderr is a file or a pipe.
RunObserver terminal_observer(const std::string& command, bool progress = false);

}  // namespace contactbench
