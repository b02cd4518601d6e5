// What a run tells the application while it works: stages as they start and finish, progress of long stages,
// warnings (a solve that did not converge). The application owns where it goes (stderr for the command line,
// a record in tests); the libraries and the pipeline never write to a stream themselves.
#pragma once

#include <functional>
#include <string>

namespace contactbench {

struct RunObserver {
  std::function<void(const std::string& stage)> stage_started;
  std::function<void(const std::string& stage, double seconds)> stage_finished;
  std::function<void(const std::string& text)> progress;  // one line of progress, no newline
  std::function<void(const std::string& text)> warning;   // one line, no newline

  void started(const std::string& stage) const {
    if (stage_started) stage_started(stage);
  }
  void finished(const std::string& stage, double seconds) const {
    if (stage_finished) stage_finished(stage, seconds);
  }
  void say(const std::string& text) const {
    if (progress) progress(text);
  }
  void warn(const std::string& text) const {
    if (warning) warning(text);
  }
};

// Long stages report progress after this many seconds (shorter ones say nothing).
inline constexpr double kProgressAfterSeconds = 2;

}  // namespace contactbench
