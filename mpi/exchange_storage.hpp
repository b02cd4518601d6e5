// Where the slab convolution's spectra wait between its passes (mpi/slab_convolution_engine.hpp), and how
// they reach the rank that transforms them: by messages (two buffers a rank, one MPI_Alltoallv each way), or,
// when every rank runs on one machine, in memory the ranks share (one MPI shared-memory window: each rank
// writes its rows' spectra into its own part, and the rank owning a column block reads and writes that block
// in the other ranks' parts in place, between two barriers; nothing is copied). docs/mpi.md "Exchanges in
// shared memory" says why and what it saved.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <mpi.h>

namespace contactbench::mpi {

enum class ExchangeTransport { messages, shared_memory };

// The environment variable that chooses the transport: `auto` (the default: shared memory when every rank of
// the communicator is on one machine and the shared-memory folder has room), `messages` or `shared_memory`.
inline constexpr const char* kExchangeVariable = "CONTACTBENCH_MPI_EXCHANGE";

// The transport for `bytes_per_rank` bytes a rank, the same on every rank (collective): the variable above
// read on each rank, a value other than the three refused by an Error naming it and them; shared memory asked
// for where the ranks are on several machines, or where /dev/shm (Open MPI's folder for shared windows) has
// less room than every rank's part, refused by an Error too.
ExchangeTransport choose_exchange_transport(MPI_Comm comm, std::size_t bytes_per_rank);

// The engine's buffers, raw bytes (FFTW's alignment): an engine's own, or shared by engines that never run at
// once (the solver's operator in double and its filter in float need the same values a point, the filter
// half the bytes). `rows`: this rank's rows' spectra; `block`, by messages only: this rank's columns of
// every rank's rows. In shared memory `rows` is this rank's part of the window and `segment(r)` rank r's
// part (read and written by this rank where its columns are).
class ExchangeStorage {
 public:
  // Collective where the transport is shared memory (the window is made by every rank together).
  ExchangeStorage(MPI_Comm comm, ExchangeTransport transport, std::size_t rows_bytes,
                  std::size_t block_bytes);
  // Collective in shared memory (the window is freed by every rank together).
  ~ExchangeStorage();
  ExchangeStorage(const ExchangeStorage&) = delete;
  ExchangeStorage& operator=(const ExchangeStorage&) = delete;

  ExchangeTransport transport() const { return transport_; }
  void* rows() const { return rows_; }
  void* block() const { return block_; }
  void* segment(int rank) const { return segments_.at(static_cast<std::size_t>(rank)); }
  // Does it have room for an engine needing these bytes? (In shared memory the block is never used.)
  bool fits(std::size_t rows_bytes, std::size_t block_bytes) const {
    return rows_bytes_ >= rows_bytes &&
           (transport_ == ExchangeTransport::shared_memory || block_bytes_ >= block_bytes);
  }
  std::size_t bytes() const { return rows_bytes_ + block_bytes_; }

  // Shared memory: every rank's writes to the window seen by every rank, once all have come here
  // (MPI_Win_sync, MPI_Barrier, MPI_Win_sync: the unified model's idiom). Collective.
  void synchronise() const;

 private:
  ExchangeTransport transport_;
  MPI_Comm comm_;
  MPI_Win window_ = MPI_WIN_NULL;
  void* rows_ = nullptr;
  void* block_ = nullptr;
  std::vector<void*> segments_;
  std::size_t rows_bytes_ = 0, block_bytes_ = 0;
};

}  // namespace contactbench::mpi
