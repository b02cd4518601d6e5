// How a result was made: commit, date, threads, machine and command, stamped on every file in results/.
#pragma once

#include <string>

namespace contactbench {

struct Provenance {
  std::string commit;   // git commit of the build ("-dirty" when the tree had changes), or "unknown"
  std::string date;     // UTC, ISO 8601
  int threads = 1;      // of each process (each MPI rank when run as several)
  int ranks = 1;        // MPI ranks (mpiexec -np K, docs/mpi.md); 1 for one process
  std::string machine;  // host name and CPU model
  std::string command;  // the command line that made the result ("mpiexec -np K ..." when run as K ranks)
};

Provenance current_provenance(int threads, const std::string& command);

// "2 threads", or "3 ranks x 1 threads" when run as several MPI ranks: what a stamp says of the cores used.
std::string threads_text(const Provenance& p);

// "contactbench <version> (commit <commit>)": what `contactbench --version` prints.
std::string version_line();

}  // namespace contactbench
