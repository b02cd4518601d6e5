// MPI's profiling interface (MPI standard, "Profiling Interface"): a program may define an MPI function
// itself and call the library's through the PMPI_ name. bench_mpi exports these definitions (ENABLE_EXPORTS),
// so FFTW-MPI's calls from its shared library reach them too.
#include "mpi_call_clock.hpp"

#include <chrono>

#include <mpi.h>

namespace contactbench::bench {
namespace {

MpiCallTimes times;

// Runs one MPI call and adds its time to `seconds`.
int timed(double& seconds, auto call) {
  const auto start = std::chrono::steady_clock::now();
  const int status = call();
  seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

int exchange(auto call) {
  return timed(times.exchange_seconds, call);
}
int reduction(auto call) {
  return timed(times.reduction_seconds, call);
}

}  // namespace

MpiCallTimes mpi_call_times() {
  return times;
}
void reset_mpi_call_times() {
  times = {};
}

}  // namespace contactbench::bench

using contactbench::bench::exchange;
using contactbench::bench::reduction;

extern "C" {

int MPI_Alltoall(const void* send, int send_count, MPI_Datatype send_type, void* receive, int receive_count,
                 MPI_Datatype receive_type, MPI_Comm comm) {
  return exchange(
      [&] { return PMPI_Alltoall(send, send_count, send_type, receive, receive_count, receive_type, comm); });
}

int MPI_Alltoallv(const void* send, const int send_counts[], const int send_offsets[], MPI_Datatype send_type,
                  void* receive, const int receive_counts[], const int receive_offsets[],
                  MPI_Datatype receive_type, MPI_Comm comm) {
  return exchange([&] {
    return PMPI_Alltoallv(send, send_counts, send_offsets, send_type, receive, receive_counts,
                          receive_offsets, receive_type, comm);
  });
}

int MPI_Alltoallw(const void* send, const int send_counts[], const int send_offsets[],
                  const MPI_Datatype send_types[], void* receive, const int receive_counts[],
                  const int receive_offsets[], const MPI_Datatype receive_types[], MPI_Comm comm) {
  return exchange([&] {
    return PMPI_Alltoallw(send, send_counts, send_offsets, send_types, receive, receive_counts,
                          receive_offsets, receive_types, comm);
  });
}

int MPI_Sendrecv(const void* send, int send_count, MPI_Datatype send_type, int destination, int send_tag,
                 void* receive, int receive_count, MPI_Datatype receive_type, int source, int receive_tag,
                 MPI_Comm comm, MPI_Status* status) {
  return exchange([&] {
    return PMPI_Sendrecv(send, send_count, send_type, destination, send_tag, receive, receive_count,
                         receive_type, source, receive_tag, comm, status);
  });
}

// The slab engine's exchange in shared memory (mpi/exchange_storage.hpp): a barrier where the messages were.
int MPI_Barrier(MPI_Comm comm) {
  return exchange([&] { return PMPI_Barrier(comm); });
}

int MPI_Allreduce(const void* send, void* receive, int count, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  return reduction([&] { return PMPI_Allreduce(send, receive, count, type, op, comm); });
}

int MPI_Allgather(const void* send, int send_count, MPI_Datatype send_type, void* receive, int receive_count,
                  MPI_Datatype receive_type, MPI_Comm comm) {
  return reduction([&] {
    return PMPI_Allgather(send, send_count, send_type, receive, receive_count, receive_type, comm);
  });
}

int MPI_Bcast(void* buffer, int count, MPI_Datatype type, int root, MPI_Comm comm) {
  return reduction([&] { return PMPI_Bcast(buffer, count, type, root, comm); });
}

}  // extern "C"
