#include "contactbench/app/cli.hpp"

#include <exception>
#include <iostream>
#include <string>

#include <omp.h>

#if CONTACTBENCH_WITH_MPI
#include "contactbench/app/distributed_stages.hpp"
#endif
#include "contactbench/app/mpi_launch.hpp"
#include "contactbench/app/output.hpp"
#include "contactbench/app/provenance.hpp"
#include "contactbench/app/stage_runner.hpp"
#include "contactbench/app/unconverged.hpp"
#include "contactbench/core/error.hpp"

namespace contactbench {

bool CommandContext::runs_as_ranks() const {
  return runner && runner->ranks() > 1;
}

void add_threads_option(CLI::App& command, int& threads) {
  threads = omp_get_max_threads();
  command.add_option("--threads", threads, "Threads for FFTs and loops (default: all cores)")
      ->check(CLI::Range(1, 1024));
}

void add_progress_option(CLI::App& command, bool& progress) {
  command.add_flag("--progress", progress,
                   "one line per stage and per load solved on stderr, even when it is not a terminal "
                   "(default: on a terminal, for stages longer than 2 s; otherwise none)");
}

int run_cli(int argc, char** argv) {
  CLI::App app{
      "contactbench: how well cheap models of rough-surface contact predict the real contact area, and what "
      "each answer costs in time."};
  app.set_version_flag("--version", version_line());
  app.require_subcommand(1);
  CommandContext context;
  add_generate_command(app);
  add_stats_command(app);
  add_sweep_command(app, context);
  add_bem_command(app, context);
  add_run_command(app, context);
  add_convert_command(app);
  add_plot_command(app);
  auto parse_and_run = [&]() -> int {
    try {
      app.parse(argc, argv);
      check_standard_output();  // a command whose output was lost must not exit 0
    } catch (const CLI::ParseError& e) {
      return app.exit(e);  // --help lands here with status 0; a usage error prints its reason
    } catch (const UnconvergedError& e) {
      std::cerr << "contactbench: error: " << e.what() << '\n';
      return kUnconvergedExitStatus;
    } catch (const std::exception& e) {
      std::cerr << "contactbench: error: " << e.what() << '\n';
      return 1;
    }
    return 0;
  };
  // Started as K > 1 MPI ranks (mpirun / mpiexec -np K): `run`, `bem` and `sweep` run their BEM and sweep
  // stages on slabs across the ranks, rank 0 doing everything else once (app/distributed_stages.hpp). Other
  // commands have nothing to distribute and K copies would each do the whole work and write the same files:
  // refused, said once (by rank 0).
  if (const MpiLaunch launch = mpi_launch(); launch.ranks > 1) {
    const std::string command = argc > 1 ? argv[1] : "";
    const bool distributable = command == "run" || command == "bem" || command == "sweep";
#if CONTACTBENCH_WITH_MPI
    if (distributable)
      return run_as_mpi_ranks(argc, argv, [&](const StageRunner& runner) {
        context.runner = &runner;
        return parse_and_run();
      });
#endif
    if (launch.rank == 0)
      std::cerr << "contactbench: error: started as " << launch.ranks << " MPI ranks (mpirun / mpiexec), but "
                << (distributable ? "this contactbench was built without MPI (CB_WITH_MPI=OFF)"
                                  : "'" + command + "' has no distributed stages (run, bem and sweep have)")
                << ": each rank would run the whole command and write the same files. Run it as one "
                   "process (docs/mpi.md)\n";
    // Only rank 0 fails: a rank that exits with an error makes mpiexec kill the others, rank 0 too, at times
    // before it has said why (seen under load); the job's status is rank 0's either way.
    return launch.rank == 0 ? 1 : 0;
  }
  return parse_and_run();
}

}  // namespace contactbench
