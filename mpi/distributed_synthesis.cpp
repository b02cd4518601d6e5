#include "contactbench/mpi/distributed_synthesis.hpp"

#include <algorithm>
#include <vector>

#include <fftw3.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/mpi/distributed_fft.hpp"
#include "contactbench/mpi/message_count.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchange are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kSynthesisExchange = "an exchange of the distributed synthesis";

constexpr Index kChunk = ReproducibleInverseFft2d::kLinesPerChunk;

// The chunks of kx columns rank r transforms: [first, last) of ceil((nx/2 + 1) / kChunk), split evenly.
struct ChunkRange {
  Index first, last;
};
ChunkRange chunks_of(Index nx, int rank, int ranks) {
  const Index chunks = (nx / 2 + 1 + kChunk - 1) / kChunk;
  return {chunks * rank / ranks, chunks * (rank + 1) / ranks};
}

// One-dimensional FFTW plans of the serial synthesis' shapes (core/fft.cpp, ReproducibleInverseFft2d), for
// new-array execution. Columns: `count` columns of ny values, `count` apart (a block of ny x count), which
// FFTW computes as the serial pass computes the same columns at stride nx/2 + 1. Rows: half-complex rows of
// nx/2 + 1 values to real rows of nx, any number of rows at a time, each row as in the serial pass.
class SynthesisPlans {
 public:
  SynthesisPlans(Index nx, Index ny) {
    const Index nxh = nx / 2 + 1;
    std::vector<Complex> scratch_spectrum(
        static_cast<std::size_t>(std::max(ny, kChunk) * std::max(nxh, kChunk)));
    std::vector<double> scratch_real(static_cast<std::size_t>(kChunk * nx));
    auto* spectrum = reinterpret_cast<fftw_complex*>(scratch_spectrum.data());
    const int n_y = static_cast<int>(ny), n_x = static_cast<int>(nx), n_xh = static_cast<int>(nxh);
    const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;  // as the serial plans: chunks at any offset
    auto lock = lock_fftw_planner();
    fftw_plan_with_nthreads(1);
    for (int count = 1; count <= static_cast<int>(kChunk); ++count) {
      columns_.push_back(fftw_plan_many_dft(1, &n_y, count, spectrum, nullptr, count, 1, spectrum, nullptr,
                                            count, 1, FFTW_BACKWARD, flags));
      rows_.push_back(fftw_plan_many_dft_c2r(1, &n_x, count, spectrum, nullptr, 1, n_xh, scratch_real.data(),
                                             nullptr, 1, n_x, flags));
      if (!columns_.back() || !rows_.back())
        throw Error("mpi: FFTW could not plan the synthesis' transforms");
    }
  }
  ~SynthesisPlans() {
    auto lock = lock_fftw_planner();
    for (fftw_plan p : columns_)
      fftw_destroy_plan(p);
    for (fftw_plan p : rows_)
      fftw_destroy_plan(p);
  }
  SynthesisPlans(const SynthesisPlans&) = delete;
  SynthesisPlans& operator=(const SynthesisPlans&) = delete;

  // A block of ny x count values (count <= kChunk), in place along y.
  void columns(Complex* block, Index count) const {
    auto* data = reinterpret_cast<fftw_complex*>(block);
    fftw_execute_dft(columns_[static_cast<std::size_t>(count - 1)], data, data);
  }
  // `count` rows (count <= kChunk) of nx/2 + 1 half-complex values into `count` rows of nx heights.
  void rows(Complex* spectrum, Index count, double* heights) const {
    fftw_execute_dft_c2r(rows_[static_cast<std::size_t>(count - 1)],
                         reinterpret_cast<fftw_complex*>(spectrum), heights);
  }

 private:
  std::vector<fftw_plan> columns_, rows_;
};

}  // namespace

SpectrumColumns synthesis_columns(Index nx, int rank, int ranks) {
  const ChunkRange chunks = chunks_of(nx, rank, ranks);
  const Index nxh = nx / 2 + 1;
  return {std::min(chunks.first * kChunk, nxh), std::min(chunks.last * kChunk, nxh)};
}

HeightMap synthesize_slab(Index nx, Index ny, const SpectrumColumnFill& fill, MPI_Comm comm) {
  const Index nxh = nx / 2 + 1;
  const Slab slab = slab_of(nx, ny, comm);
  const auto slabs = all_slabs(nx, ny, comm);
  const int ranks = size_of(comm), me = rank_of(comm);
  const ChunkRange mine = chunks_of(nx, me, ranks);
  const SpectrumColumns columns = synthesis_columns(nx, me, ranks);
  const SynthesisPlans plans(nx, ny);

  // 1. This rank's columns, chunk by chunk, each a block of ny x width: the spectrum's values, then
  //    transformed along y.
  std::vector<Complex> blocks(static_cast<std::size_t>(ny * columns.count()));
  for (Index chunk = mine.first; chunk < mine.last; ++chunk) {
    const Index column = chunk * kChunk, width = std::min(kChunk, nxh - column);
    Complex* block = blocks.data() + ny * (column - columns.first);
    fill(column, width, block);
    plans.columns(block, width);
  }

  // 2. Columns to rows: every rank sends each destination that destination's rows of each of its blocks, in
  //    chunk order; the receiver knows every sender's chunks, so it knows where each value goes.
  std::vector<int> send_counts, send_offsets, receive_counts, receive_offsets;
  std::vector<Complex> send(static_cast<std::size_t>(std::max<Index>(ny * columns.count(), 1)));
  Index sent = 0, received = 0;
  for (int r = 0; r < ranks; ++r) {
    const Slab& destination = slabs[static_cast<std::size_t>(r)];
    send_offsets.push_back(message_count(2 * sent, kSynthesisExchange));
    for (Index chunk = mine.first; chunk < mine.last; ++chunk) {
      const Index column = chunk * kChunk, width = std::min(kChunk, nxh - column);
      const Complex* block = blocks.data() + ny * (column - columns.first);
      for (Index row = destination.start; row < destination.start + destination.count; ++row)
        for (Index j = 0; j < width; ++j)
          send[static_cast<std::size_t>(sent++)] = block[row * width + j];
    }
    send_counts.push_back(message_count(2 * sent, kSynthesisExchange) - send_offsets.back());
    const Index their_columns = synthesis_columns(nx, r, ranks).count();
    receive_offsets.push_back(message_count(2 * received, kSynthesisExchange));
    receive_counts.push_back(message_count(2 * slab.count * their_columns, kSynthesisExchange));
    received += slab.count * their_columns;
  }
  std::vector<Complex> receive(static_cast<std::size_t>(std::max<Index>(received, 1)));
  MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_DOUBLE, receive.data(),
                receive_counts.data(), receive_offsets.data(), MPI_DOUBLE, comm);
  std::vector<Complex>().swap(blocks);
  std::vector<Complex>().swap(send);

  // Unpack into this rank's rows of the half spectrum, count x (nx/2 + 1).
  std::vector<Complex> rows(static_cast<std::size_t>(std::max<Index>(slab.count * nxh, 1)));
  Index position = 0;
  for (int r = 0; r < ranks; ++r) {
    const ChunkRange theirs = chunks_of(nx, r, ranks);
    for (Index chunk = theirs.first; chunk < theirs.last; ++chunk) {
      const Index column = chunk * kChunk, width = std::min(kChunk, nxh - column);
      for (Index row = 0; row < slab.count; ++row)
        for (Index j = 0; j < width; ++j)
          rows[static_cast<std::size_t>(row * nxh + column + j)] = receive[position++];
    }
  }
  std::vector<Complex>().swap(receive);

  // 3. Along x, in chunks of rows.
  HeightMap heights(slab.count, nx);
  for (Index row = 0; row < slab.count; row += kChunk) {
    const Index count = std::min(kChunk, slab.count - row);
    plans.rows(rows.data() + row * nxh, count, heights.data() + row * nx);
  }
  return heights;
}

}  // namespace contactbench::mpi
