#include "contactbench/mpi/exchange_storage.hpp"

#include <sys/statvfs.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#include <fftw3.h>

#include "contactbench/core/error.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

namespace {

// Open MPI's shared windows are files in this folder (its osc_sm_backing_directory's default); a window
// larger than its free room would fail on first touch (SIGBUS), not at allocation, so the room is checked
// first. A tmpfs such as a container's 64 MB /dev/shm is the case this guards.
constexpr const char* kSharedMemoryFolder = "/dev/shm";

// A cache line, the alignment a part of the shared window starts at.
constexpr std::size_t kLine = 64;

void* at_line(void* address) {
  const auto value = reinterpret_cast<std::uintptr_t>(address);
  return reinterpret_cast<void*>((value + kLine - 1) / kLine * kLine);
}

enum class Requested { automatic, messages, shared_memory };

Requested requested_transport() {
  const char* value = std::getenv(kExchangeVariable);
  const std::string text = value ? value : "";
  if (text.empty() || text == "auto") return Requested::automatic;
  if (text == "messages") return Requested::messages;
  if (text == "shared_memory") return Requested::shared_memory;
  throw Error(std::string(kExchangeVariable) + "=" + text + ": not a transport; accepted: auto, messages, " +
              "shared_memory");
}

bool all_ranks(bool mine, MPI_Comm comm) {
  int value = mine ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_INT, MPI_LAND, comm);
  return value != 0;
}

// Room in the shared-memory folder for every rank's part (the largest times the ranks), with an eighth to
// spare. Collective.
bool shared_memory_has_room(MPI_Comm comm, std::size_t bytes_per_rank) {
  double largest = static_cast<double>(bytes_per_rank);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_DOUBLE, MPI_MAX, comm);
  struct statvfs folder {};
  const bool readable = statvfs(kSharedMemoryFolder, &folder) == 0;
  const double room =
      readable ? static_cast<double>(folder.f_bavail) * static_cast<double>(folder.f_frsize) : 0;
  return all_ranks(room >= 1.125 * largest * size_of(comm), comm);
}

}  // namespace

ExchangeTransport choose_exchange_transport(MPI_Comm comm, std::size_t bytes_per_rank) {
  // Read on every rank; a refusal on one is a refusal on all, so that no rank waits for another that threw.
  std::string refusal;
  Requested requested = Requested::automatic;
  try {
    requested = requested_transport();
  } catch (const Error& e) {
    refusal = e.what();
  }
  throw_on_any_rank(!refusal.empty(), refusal, comm);
  // The same answer on every rank: the choice is each rank's, agreed by all.
  const bool asked_for_messages = !all_ranks(requested != Requested::messages, comm);
  if (asked_for_messages || size_of(comm) == 1) return ExchangeTransport::messages;
  const bool forced = !all_ranks(requested != Requested::shared_memory, comm);
  if (!all_ranks(ranks_sharing_memory(comm) == size_of(comm), comm)) {
    if (forced)
      throw Error(std::string(kExchangeVariable) +
                  "=shared_memory: the ranks are on several machines; accepted there: auto, messages");
    return ExchangeTransport::messages;
  }
  if (!shared_memory_has_room(comm, bytes_per_rank)) {
    if (forced)
      throw Error(std::string(kExchangeVariable) + "=shared_memory: " + kSharedMemoryFolder +
                  " has too little room for the ranks' exchange (about " +
                  std::to_string(bytes_per_rank * size_of(comm)) + " bytes); accepted here: auto, messages");
    return ExchangeTransport::messages;
  }
  return ExchangeTransport::shared_memory;
}

ExchangeStorage::ExchangeStorage(MPI_Comm comm, ExchangeTransport transport, std::size_t rows_bytes,
                                 std::size_t block_bytes)
    : transport_(transport), comm_(comm), rows_bytes_(rows_bytes) {
  if (transport == ExchangeTransport::messages) {
    block_bytes_ = block_bytes;
    rows_ = fftw_malloc(std::max<std::size_t>(rows_bytes, 16));
    block_ = fftw_malloc(std::max<std::size_t>(block_bytes, 16));
    if (!rows_ || !block_) {
      fftw_free(rows_);
      fftw_free(block_);
      throw Error("mpi: out of memory for the slab convolution's exchange buffers");
    }
    return;
  }
  // Each rank's part on its own pages (not packed after the previous rank's), each started at its first
  // cache line (Open MPI 4.1 gives 8-byte aligned parts; FFTW writes a part in place and wants the alignment
  // fftw_malloc gives). A part's place within its page is the same in every process that maps it, so each
  // rank finds the same line in the others' parts.
  MPI_Info info = MPI_INFO_NULL;
  MPI_Info_create(&info);
  MPI_Info_set(info, "alloc_shared_noncontig", "true");
  void* base = nullptr;
  const int made =
      MPI_Win_allocate_shared(static_cast<MPI_Aint>(rows_bytes + kLine), 1, info, comm, &base, &window_);
  MPI_Info_free(&info);
  if (!all_ranks(made == MPI_SUCCESS, comm)) {
    if (made == MPI_SUCCESS) MPI_Win_free(&window_);
    throw Error("mpi: the slab convolution's shared-memory window could not be made; set " +
                std::string(kExchangeVariable) + "=messages");
  }
  for (int r = 0; r < size_of(comm); ++r) {
    MPI_Aint size = 0;
    int unit = 0;
    MPI_Win_shared_query(window_, r, &size, &unit, &base);
    segments_.push_back(at_line(base));
  }
  rows_ = segments_.at(static_cast<std::size_t>(rank_of(comm)));
  // One passive epoch for the window's life: its accesses are plain loads and stores, ordered by
  // synchronise().
  MPI_Win_lock_all(MPI_MODE_NOCHECK, window_);
}

ExchangeStorage::~ExchangeStorage() {
  if (window_ != MPI_WIN_NULL) {
    MPI_Win_unlock_all(window_);
    MPI_Win_free(&window_);
    return;
  }
  fftw_free(rows_);
  fftw_free(block_);
}

void ExchangeStorage::synchronise() const {
  MPI_Win_sync(window_);
  MPI_Barrier(comm_);
  MPI_Win_sync(window_);
}

}  // namespace contactbench::mpi
