#include "contactbench/mpi/distributed_generation.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <fftw3.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/mpi/distributed_fft.hpp"
#include "contactbench/mpi/message_count.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchanges are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kGenerationExchange = "an exchange of the distributed generation";

constexpr Index kChunk = ReproducibleInverseFft2d::kLinesPerChunk;

// The chunks of kx columns rank r transforms: [first, last) of ceil((nx/2 + 1) / kChunk), split evenly.
struct ChunkRange {
  Index first, last;
};
ChunkRange chunks_of(int rank, int ranks, Index chunks) {
  return {chunks * rank / ranks, chunks * (rank + 1) / ranks};
}

// One-dimensional FFTW plans of the serial generator's shapes (core/fft.cpp, ReproducibleInverseFft2d), for
// new-array execution. Columns: `count` columns of ny values, `count` apart (a block of ny x count), which
// FFTW computes as the serial pass computes the same columns at stride nx/2 + 1. Rows: half-complex rows of
// nx/2 + 1 values to real rows of nx, any number of rows at a time, each row as in the serial pass.
class GeneratorPlans {
 public:
  GeneratorPlans(Index nx, Index ny) {
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
        throw Error("mpi: FFTW could not plan the generator's transforms");
    }
  }
  ~GeneratorPlans() {
    auto lock = lock_fftw_planner();
    for (fftw_plan p : columns_)
      fftw_destroy_plan(p);
    for (fftw_plan p : rows_)
      fftw_destroy_plan(p);
  }
  GeneratorPlans(const GeneratorPlans&) = delete;
  GeneratorPlans& operator=(const GeneratorPlans&) = delete;

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

HeightMap generate_surface_slab(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed,
                                MPI_Comm comm) {
  const SelfAffineModes modes(grid,
                              psd);  // validates, and sums the normalisation as the serial generator does
  const Index nx = grid.nx, ny = grid.ny, nxh = nx / 2 + 1;
  const Slab slab = slab_of(grid, comm);
  const auto slabs = all_slabs(nx, ny, comm);
  const int ranks = size_of(comm), me = rank_of(comm);
  const Index chunks = (nxh + kChunk - 1) / kChunk;
  const ChunkRange mine = chunks_of(me, ranks, chunks);
  const Index first_column = std::min(mine.first * kChunk, nxh),
              last_column = std::min(mine.last * kChunk, nxh);
  const GeneratorPlans plans(nx, ny);

  // 1. This rank's columns, chunk by chunk, each a block of ny x width: the coefficients, added to zero as
  // the
  //    serial generator embeds them (core/generation.cpp, synthesize), then transformed along y.
  std::vector<Complex> blocks(static_cast<std::size_t>(ny * (last_column - first_column)));
  for (Index chunk = mine.first; chunk < mine.last; ++chunk) {
    const Index column = chunk * kChunk, width = std::min(kChunk, nxh - column);
    Complex* block = blocks.data() + ny * (column - first_column);
    for (Index row = 0; row < ny; ++row)
      for (Index j = 0; j < width; ++j) {
        Complex value(0.0, 0.0);
        value += modes.coefficient(row, column + j, seed);
        block[row * width + j] = value;
      }
    plans.columns(block, width);
  }

  // 2. Columns to rows: every rank sends each destination that destination's rows of each of its blocks, in
  //    chunk order; the receiver knows every sender's chunks, so it knows where each value goes.
  std::vector<int> send_counts, send_offsets, receive_counts, receive_offsets;
  std::vector<Complex> send(static_cast<std::size_t>(std::max<Index>(ny * (last_column - first_column), 1)));
  Index sent = 0, received = 0;
  for (int r = 0; r < ranks; ++r) {
    const Slab& destination = slabs[static_cast<std::size_t>(r)];
    send_offsets.push_back(message_count(2 * sent, kGenerationExchange));
    for (Index chunk = mine.first; chunk < mine.last; ++chunk) {
      const Index column = chunk * kChunk, width = std::min(kChunk, nxh - column);
      const Complex* block = blocks.data() + ny * (column - first_column);
      for (Index row = destination.start; row < destination.start + destination.count; ++row)
        for (Index j = 0; j < width; ++j)
          send[static_cast<std::size_t>(sent++)] = block[row * width + j];
    }
    send_counts.push_back(message_count(2 * sent, kGenerationExchange) - send_offsets.back());
    const ChunkRange theirs = chunks_of(r, ranks, chunks);
    const Index their_columns = std::min(theirs.last * kChunk, nxh) - std::min(theirs.first * kChunk, nxh);
    receive_offsets.push_back(message_count(2 * received, kGenerationExchange));
    receive_counts.push_back(message_count(2 * slab.count * their_columns, kGenerationExchange));
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
    const ChunkRange theirs = chunks_of(r, ranks, chunks);
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

SpectralMoments distributed_spectral_moments(const Grid& grid, const HeightMap& local_heights,
                                             MPI_Comm comm) {
  validate(grid, "distributed moments grid");
  DistributedRealFft2d fft(grid.nx, grid.ny, comm);
  const Slab& slab = fft.slab();
  throw_on_any_rank(local_heights.rows() != slab.count || local_heights.cols() != grid.nx,
                    "mpi: moments: the local heights are " + std::to_string(local_heights.cols()) + " x " +
                        std::to_string(local_heights.rows()) + " but this rank's slab is " +
                        std::to_string(grid.nx) + " x " + std::to_string(slab.count),
                    comm);
  const Real mean = sum_over_ranks(local_heights.sum(), comm) / static_cast<Real>(grid.points());
  // The Hann window of core/spectrum.cpp, sin^2(pi (i + 1/2) / n), separable and normalised by its rms.
  auto hann = [](Index i, Index n) {
    const Real s = std::sin(std::numbers::pi * (static_cast<Real>(i) + 0.5) / static_cast<Real>(n));
    return s * s;
  };
  const bool windowed = default_window(grid) == Window::hann;
  Real rms_window = 1;
  if (windowed) {
    Real sx = 0, sy = 0;
    for (Index i = 0; i < grid.nx; ++i)
      sx += hann(i, grid.nx) * hann(i, grid.nx);
    for (Index i = 0; i < grid.ny; ++i)
      sy += hann(i, grid.ny) * hann(i, grid.ny);
    rms_window = std::sqrt(sx / static_cast<Real>(grid.nx) * (sy / static_cast<Real>(grid.ny)));
  }
  for (Index r = 0; r < slab.count; ++r) {
    double* row = fft.real_row(r);
    const Real wy = windowed ? hann(slab.start + r, grid.ny) : 1.0;
    for (Index x = 0; x < grid.nx; ++x)
      row[x] = (local_heights(r, x) - mean) * (windowed ? wy * hann(x, grid.nx) / rms_window : 1.0);
  }
  fft.forward();

  // Sums over this rank's spectral columns (each weighted by the full-lattice modes it stands for), then
  // over the ranks. The mean (k = 0) is excluded, as in the serial moments.
  const HalfLattice lattice(grid);
  const Real norm = static_cast<Real>(grid.points());
  double sums[5] = {0, 0, 0, 0, 0};  // m0, m2x, m4x, m2y, m4y
  const Complex* spectrum = fft.spectrum();
  for (Index c = 0; c < fft.spectrum_count(); ++c) {
    const Index col = fft.spectrum_start() + c;
    const Real qx2 = lattice.qx(col) * lattice.qx(col), weight = lattice.multiplicity(col);
    for (Index row = 0; row < grid.ny; ++row) {
      if (row == 0 && col == 0) continue;
      const Real power = weight * std::norm(spectrum[c * grid.ny + row] / norm);
      const Real qy2 = lattice.qy(row) * lattice.qy(row);
      sums[0] += power;
      sums[1] += power * qx2;
      sums[2] += power * qx2 * qx2;
      sums[3] += power * qy2;
      sums[4] += power * qy2 * qy2;
    }
  }
  double totals[5];
  MPI_Allreduce(sums, totals, 5, MPI_DOUBLE, MPI_SUM, comm);
  SpectralMoments m;
  m.m0 = totals[0];
  m.m2x = totals[1];
  m.m4x = totals[2];
  m.m2y = totals[3];
  m.m4y = totals[4];
  return m;
}

}  // namespace contactbench::mpi
