// FFTW-MPI's 2D real <-> half-complex transform of an nx x ny grid split in slabs (docs/mpi.md), in place,
// with the spectrum left transposed (FFTW_MPI_TRANSPOSED_OUT / _IN): the global transpose is done once per
// direction, and each rank holds whole spectral columns, kx in [spectrum_start, spectrum_start +
// spectrum_count), each a contiguous run of ny values over ky (FFTW order: 0, 1, ..., then negatives).
// Conventions as core/fft.hpp: forward unnormalised exp(-i q.x), backward unnormalised exp(+i q.x).
#pragma once

#include <cstddef>

#include <mpi.h>

#include <fftw3.h>

#include "contactbench/core/types.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

// The spectral columns [start, start + count) of the nx/2 + 1 that rank `comm` holds in
// DistributedRealFft2d's transposed spectrum (FFTW-MPI's split), without making the transform. Collective
// only in that every rank must agree on nx, ny.
struct SpectrumColumns2d {
  Index start = 0, count = 0;
};
SpectrumColumns2d spectrum_columns(Index nx, Index ny, MPI_Comm comm);

class DistributedRealFft2d {
 public:
  // Collective: every rank of comm constructs it with the same nx, ny. Runs FFTW on `threads` threads a rank.
  DistributedRealFft2d(Index nx, Index ny, MPI_Comm comm, int threads = 1);
  ~DistributedRealFft2d();
  DistributedRealFft2d(const DistributedRealFft2d&) = delete;
  DistributedRealFft2d& operator=(const DistributedRealFft2d&) = delete;

  const Slab& slab() const { return slab_; }
  MPI_Comm comm() const { return comm_; }
  Index nx_half() const { return slab_.nx / 2 + 1; }
  Index spectrum_start() const { return spectrum_start_; }
  Index spectrum_count() const { return spectrum_count_; }

  // Row r (0 <= r < slab().count) of this rank's real slab: nx values, then FFTW's in-place padding.
  double* real_row(Index r) { return reinterpret_cast<double*>(data_) + r * 2 * nx_half(); }
  // This rank's spectral columns: value (kx - spectrum_start, ky) at spectrum()[(kx - start) * ny + ky].
  Complex* spectrum() { return reinterpret_cast<Complex*>(data_); }

  // Bytes this rank holds for the transform (its in-place slab, as FFTW-MPI sizes it).
  std::size_t bytes() const { return bytes_; }

  void forward();   // spectrum() <- forward(real slab); collective
  void backward();  // real slab <- backward(spectrum()); collective

  // Copying conveniences: a count x nx row-major slab in, or out.
  void load(const Real* slab_values);
  void store(Real* slab_values);

 private:
  Slab slab_;
  MPI_Comm comm_;
  Index spectrum_start_ = 0, spectrum_count_ = 0;
  fftw_complex* data_ = nullptr;
  std::size_t bytes_ = 0;
  fftw_plan forward_plan_ = nullptr, backward_plan_ = nullptr;
};

}  // namespace contactbench::mpi
