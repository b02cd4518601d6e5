// The contactbench command line: subcommands, their options, and how errors reach the user.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "contactbench/app/run_observer.hpp"

namespace contactbench {

// Parses argv and runs the chosen subcommand. Returns the process exit status: 0 on success; on any error a
// one-line reason on stderr and a non-zero status (2 for bad usage, 1 for bad input or a failed run).
int run_cli(int argc, char** argv);

class StageRunner;  // app/stage_runner.hpp

// What the scene commands share, chosen once by run_cli before any command parses: where their stages run
// (this process, or slabs across MPI ranks). Never changes how a scene is read.
struct CommandContext {
  const StageRunner* runner = nullptr;  // null: this process
  bool runs_as_ranks() const;           // started as several MPI ranks (the runner spreads the stages)
};

// Each subcommand registers its options on `parent` and runs when chosen (one file each). The scene
// commands read `context` when they run.
void add_generate_command(CLI::App& parent);
void add_stats_command(CLI::App& parent);
void add_sweep_command(CLI::App& parent, const CommandContext& context);
void add_bem_command(CLI::App& parent, const CommandContext& context);
void add_run_command(CLI::App& parent, const CommandContext& context);
void add_convert_command(CLI::App& parent);
void add_plot_command(CLI::App& parent);

// --progress: the option that sets `progress` for terminal_observer (app/run_observer.hpp).
void add_progress_option(CLI::App& command, bool& progress);

// Threads for a command: --threads if given, else what OpenMP would use (the machine's cores).
void add_threads_option(CLI::App& command, int& threads);

}  // namespace contactbench
