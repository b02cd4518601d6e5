// The FFTW wisdom file of a solving command (bem, run): which file, read when the command starts (before any
// plan is made) and written back once when its solves are done, so that FFTW_MEASURE's planning is paid on a
// machine's first run and not on every run (docs/solvers.md, Planning).
//
// Which file: --fftw-wisdom FILE, else the variable CONTACTBENCH_FFTW_WISDOM, else the user's cache folder,
// $XDG_CACHE_HOME/contactbench/ or ~/.cache/contactbench/, one file per key (core/fftw_wisdom.hpp); `none`
// keeps no file. Wisdom only ever saves time: a bad file or an unwritable folder is a warning naming it.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "contactbench/core/fft.hpp"

namespace contactbench {

inline constexpr const char* kFftwWisdomVariable = "CONTACTBENCH_FFTW_WISDOM";

// Registers --fftw-wisdom FILE on `command` (`file` stays empty when not given).
void add_fftw_wisdom_option(CLI::App& command, std::string& file);

// The file a command keeps wisdom in: `option` (--fftw-wisdom) when given, else the variable, else the cache
// folder's file for this key; nothing for `none`, or when there is no cache folder (no XDG_CACHE_HOME and no
// HOME). `distributed`: run as MPI ranks (core/fftw_wisdom.hpp fftw_wisdom_key: a file of its own).
std::optional<std::filesystem::path> fftw_wisdom_path(const std::string& option, int threads,
                                                      bool distributed = false);

class FftwWisdomFile {
 public:
  using Warn = std::function<void(const std::string&)>;

  // Imports the wisdom of the file fftw_wisdom_path(option, threads, distributed) names into FFTW's
  // planners, warning when it is unusable (foreign, damaged, not a wisdom file at all). While it lives, the
  // planner is told whether the wisdom is kept (core/fft.hpp FftWork: the finest grids are then measured,
  // once per machine).
  FftwWisdomFile(const std::string& option, int threads, bool distributed, Warn warn);
  // Saves, if save() was not called (an error ended the command: the plans measured are still good).
  ~FftwWisdomFile();
  FftwWisdomFile(const FftwWisdomFile&) = delete;
  FftwWisdomFile& operator=(const FftwWisdomFile&) = delete;

  // Writes the planners' wisdom to the file when it differs from what the file holds, merged first with what
  // another process may have written meanwhile; atomically, once. A file that is not a wisdom file is
  // never replaced. Warns, never throws.
  void save();

  // For the run's stage line: "cached in FILE", "not kept" and the like.
  std::string describe() const;

  // Whether what the planners measure is written to a file (a path, and not a foreign file left untouched).
  bool kept() const { return path_.has_value() && replaceable_; }

 private:
  std::optional<std::filesystem::path> path_;
  std::string key_;
  std::string learned_by_start_;  // FFTW's wisdom once the file was read: a save without news writes nothing
  Warn warn_;
  bool replaceable_ = true;  // false for an existing file that is not a wisdom file
  bool imported_ = false;
  bool saved_ = false;
  FftWork work_before_;  // the planner's FftWork before this file, given back when it goes
};

}  // namespace contactbench
