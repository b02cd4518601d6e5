// The distributed tests' main: MPI and FFTW-MPI up for the whole run (mpi/environment.hpp), then GoogleTest
// on every rank. Each rank runs every test (the tests are collective); any failure on any rank makes that
// rank, and so mpiexec, exit non-zero. Only rank 0 prints the per-test progress.
#include <gtest/gtest.h>

#include "contactbench/mpi/environment.hpp"
#include "contactbench/mpi/slab.hpp"

int main(int argc, char** argv) {
  contactbench::mpi::Environment environment(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (contactbench::mpi::rank_of(MPI_COMM_WORLD) != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new ::testing::EmptyTestEventListener);  // failures still reach stderr via the assertion
  }
  const int failed = RUN_ALL_TESTS();
  // Every rank's verdict, so that one rank's failure fails the run however mpiexec reports exit codes.
  int any_failed = 0;
  MPI_Allreduce(&failed, &any_failed, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return any_failed != 0 ? 1 : 0;
}
