// out = IDFT(M . DFT(in)) on a grid split in slabs (docs/mpi.md), for a real multiplier M given on this
// rank's spectral columns: circular on the grid, or linear by zero padding to 2 nx x 2 ny
// (bem/convolution.hpp's two cases). The transform is FFTW-MPI's (mpi/distributed_fft.hpp). Padded, the
// transform's lattice is split in slabs of its own 2 ny rows, and the grid's rows travel to those slabs and
// back by one MPI_Alltoallv each way. The half-space operators and the solver's Fourier preconditioner are
// such convolutions.
#pragma once

#include <memory>
#include <vector>

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/mpi/distributed_fft.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

class DistributedConvolution {
 public:
  // Collective; the multiplier is zero until set.
  DistributedConvolution(const Grid& grid, bool padded, MPI_Comm comm, int threads = 1);
  ~DistributedConvolution();

  const Slab& slab() const { return slab_; }  // of the grid: the input's and output's layout
  bool padded() const { return padded_; }
  Index lx() const { return lx_; }  // the transform's lattice: nx x ny, or 2 nx x 2 ny padded
  Index ly() const { return ly_; }
  // The transform, for filling its real slab (a kernel) and reading its spectrum when making a multiplier.
  DistributedRealFft2d& transform() { return *fft_; }

  // M on this rank's spectral columns, value (kx - spectrum_start, ky) at [(kx - spectrum_start) * ly + ky],
  // the pair's normalisation 1/(lx ly) folded in. Collective (sums G(0) over the ranks).
  void set_multiplier(std::vector<double> multiplier);
  // G(0): the output at a point of a unit input at that point alone, the sum of M over the full lattice.
  double self_response() const { return self_response_; }

  // Bytes this rank holds for the convolution: the transform's slab, the multiplier, the exchange buffer.
  std::size_t bytes() const {
    return fft_->bytes() + sizeof(double) * (multiplier_.capacity() + receive_buffer_.capacity());
  }

  // out = conv(in) on this rank's slab (count x nx, row-major); in and out may be the same array. Collective.
  void apply(const Real* in, Real* out);

 private:
  Slab slab_;
  MPI_Comm comm_;
  bool padded_;
  Index lx_, ly_;
  std::unique_ptr<DistributedRealFft2d> fft_;
  std::vector<double> multiplier_;
  double self_response_ = 0;
  // Padded only: how the grid's rows travel to the transform's slabs (counts, offsets in values), and the
  // transform slab's grid rows in row order.
  std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
  std::vector<double> receive_buffer_;
};

}  // namespace contactbench::mpi
