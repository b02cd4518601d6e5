#include "contactbench/mpi/distributed_refinement.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/mpi/distributed_synthesis.hpp"
#include "contactbench/mpi/message_count.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchange are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kRefinementExchange = "the coefficients' scatter of the distributed refinement";

// The surface's coefficients' columns [first, last) that a rank's columns of the finer half spectrum hold:
// the finer lattice keeps every coarse kx column at the same index, and its columns beyond the coarse
// ones are zero.
SpectrumColumns coarse_columns_of(Index fine_nx, Index coarse_columns, int rank, int ranks) {
  const SpectrumColumns fine = synthesis_columns(fine_nx, rank, ranks);
  return {std::min(fine.first, coarse_columns), std::min(fine.last, coarse_columns)};
}

}  // namespace

RefinedSlab refine_surface_slab(const Surface* root_surface, Index nx, Index ny, int threads, MPI_Comm comm) {
  const int ranks = size_of(comm), me = rank_of(comm);
  throw_on_any_rank(me == 0 && !root_surface, "mpi: refinement: rank 0 has no surface to refine", comm);

  // The coarse grid and the finer size, rank 0's, on every rank: each rank checks what the serial
  // refinement checks, so that all throw alike.
  double sizes[7] = {};
  if (me == 0) {
    const Grid& g = root_surface->grid();
    const double mine[7] = {
        static_cast<double>(g.nx), static_cast<double>(g.ny), g.lx, g.ly, g.periodic ? 1.0 : 0.0,
        static_cast<double>(nx),   static_cast<double>(ny)};
    std::copy(mine, mine + 7, sizes);
  }
  MPI_Bcast(sizes, 7, MPI_DOUBLE, 0, comm);
  const Grid coarse{.nx = static_cast<Index>(sizes[0]),
                    .ny = static_cast<Index>(sizes[1]),
                    .lx = sizes[2],
                    .ly = sizes[3],
                    .periodic = sizes[4] != 0};
  nx = static_cast<Index>(sizes[5]);
  ny = static_cast<Index>(sizes[6]);
  if (!coarse.periodic)  // core/generation.cpp, refine
    throw Error("refine: Fourier interpolation assumes a periodic surface; this one is not periodic");
  validate(coarse, "synthesis grid");  // core/generation.cpp, synthesize
  if (nx < coarse.nx || ny < coarse.ny)
    throw Error("Fourier interpolation goes to a finer grid only: asked for " + std::to_string(nx) + " x " +
                std::to_string(ny) + " from " + std::to_string(coarse.nx) + " x " +
                std::to_string(coarse.ny));

  // The coefficients on rank 0, as core's refine takes them (the mean kept), each rank's columns sent to it.
  const HalfLattice source(coarse);
  const Index coarse_columns = source.cols();
  std::vector<int> counts, offsets;
  std::vector<Complex> packed;
  if (me == 0) {
    FourierCoefficients c = fourier_coefficients(*root_surface, Window::none, threads);
    c.hhat(0, 0) = root_surface->mean_height();
    packed.reserve(static_cast<std::size_t>(c.hhat.size()));
    for (int r = 0; r < ranks; ++r) {
      const SpectrumColumns theirs = coarse_columns_of(nx, coarse_columns, r, ranks);
      offsets.push_back(message_count(2 * static_cast<Index>(packed.size()), kRefinementExchange));
      for (Index row = 0; row < coarse.ny; ++row)
        for (Index col = theirs.first; col < theirs.last; ++col)
          packed.push_back(c.hhat(row, col));
      counts.push_back(message_count(2 * static_cast<Index>(packed.size()), kRefinementExchange) -
                       offsets.back());
    }
  }
  const SpectrumColumns mine = coarse_columns_of(nx, coarse_columns, me, ranks);
  std::vector<Complex> columns(static_cast<std::size_t>(std::max<Index>(coarse.ny * mine.count(), 1)));
  MPI_Scatterv(packed.data(), counts.data(), offsets.data(), MPI_DOUBLE, columns.data(),
               message_count(2 * coarse.ny * mine.count(), kRefinementExchange), MPI_DOUBLE, 0, comm);
  std::vector<Complex>().swap(packed);

  // Where each coarse row lands in the finer lattice (core/generation.cpp, synthesize): at the same ky, the
  // coarse Nyquist row split into +ky and -ky with half each when the finer lattice has both; likewise the
  // Nyquist column, whose -kx half Hermitian symmetry implies. A finer row's sources in increasing coarse
  // row, the order in which the serial embedding adds them.
  const bool split_column = nx > coarse.nx, split_row = ny > coarse.ny;
  struct RowSource {
    Index coarse_row;
    bool half;
  };
  std::vector<std::vector<RowSource>> sources(static_cast<std::size_t>(ny));
  for (Index row = 0; row < coarse.ny; ++row) {
    const Index ky = source.ky(row);
    if (split_row && source.nyquist_row(row)) {
      sources[static_cast<std::size_t>(ny + ky)].push_back({row, true});
      sources[static_cast<std::size_t>(-ky)].push_back({row, true});
    } else {
      sources[static_cast<std::size_t>((ky + ny) % ny)].push_back({row, false});
    }
  }
  const auto embedded = [&](Index first, Index width, Complex* block) {
    for (Index row = 0; row < ny; ++row)
      for (Index j = 0; j < width; ++j) {
        const Index col = first + j;
        Complex sum(0.0, 0.0);  // the serial embedding's zeros, each value added to them
        if (col < coarse_columns)
          for (const RowSource& from : sources[static_cast<std::size_t>(row)]) {
            Complex value =
                columns[static_cast<std::size_t>(from.coarse_row * mine.count() + col - mine.first)];
            if (split_column && source.nyquist_col(col)) value *= 0.5;
            if (from.half)
              sum += 0.5 * value;
            else
              sum += value;
          }
        block[row * width + j] = sum;
      }
  };
  Grid fine = coarse;
  fine.nx = nx;
  fine.ny = ny;
  return {fine, synthesize_slab(nx, ny, embedded, comm)};
}

}  // namespace contactbench::mpi
