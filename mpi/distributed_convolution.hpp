// out = IDFT(M . DFT(in)) on a grid split in slabs (docs/mpi.md), for a real multiplier M given on this
// rank's spectral columns: circular on the grid, or linear by zero padding to 2 nx x 2 ny
// (bem/convolution.hpp's two cases). The transform is FFTW-MPI's (mpi/distributed_fft.hpp). Padded, the
// transform's lattice is split in slabs of its own 2 ny rows, and the grid's rows travel to those slabs and
// back by one MPI_Alltoallv each way. The half-space operators and the solver's Fourier preconditioner are
// such convolutions.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <mpi.h>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/mpi/distributed_fft.hpp"
#include "contactbench/mpi/slab.hpp"
#include "contactbench/mpi/slab_convolution_engine.hpp"

namespace contactbench::mpi {

class DistributedConvolution {
 public:
  // Collective; the multiplier is zero until set. `share`: another convolution of the same grid and lattice
  // whose transform and exchange buffers this one uses too (a convolution's transform is scratch between
  // two applications, so two that never run at once need one: docs/mpi.md "Memory a point").
  // `single_precision`: where the slab engine or the serial one runs (one thread a rank), the transform in
  // float, the rows produced rounded to float (the solver's filter, whose serial transform is in single
  // precision); with several threads a rank (FFTW-MPI's pair) in double.
  DistributedConvolution(const Grid& grid, bool padded, MPI_Comm comm, int threads = 1,
                         const DistributedConvolution* share = nullptr, bool single_precision = false);
  ~DistributedConvolution();

  const Slab& slab() const { return slab_; }  // of the grid: the input's and output's layout
  bool padded() const { return padded_; }
  Index lx() const { return lx_; }  // the transform's lattice: nx x ny, or 2 nx x 2 ny padded
  Index ly() const { return ly_; }
  // The transform, for filling its real slab (a kernel) and reading its spectrum when making a multiplier
  // (Love's kernel, padded): where the slab engine runs, made on this first call, collectively, and freed by
  // set_multiplier.
  DistributedRealFft2d& transform();
  // This rank's spectral columns kx of the transform's lattice, where its multiplier is given.
  Index spectrum_start() const { return spectrum_.start; }
  Index spectrum_count() const { return spectrum_.count; }

  // M on this rank's spectral columns, value (kx - spectrum_start, ky) at [(kx - spectrum_start) * ly + ky],
  // the pair's normalisation 1/(lx ly) folded in. Collective (sums G(0) over the ranks).
  void set_multiplier(std::vector<double> multiplier);
  // G(0): the output at a point of a unit input at that point alone, the sum of M over the full lattice.
  double self_response() const { return self_response_; }

  // Bytes this rank holds for the convolution: the transform's slab, the multiplier, the exchange buffers.
  std::size_t bytes() const {
    return own_bytes() + (fft_ ? fft_->bytes() : 0) +
           sizeof(double) * (buffers_->receive.capacity() + buffers_->padded_rows.capacity()) +
           (engine_ ? engine_->bytes() : 0);
  }
  // The same without what it may share with another (the transform, the exchange buffers, the double
  // engine).
  std::size_t own_bytes() const {
    return sizeof(double) * (multiplier_.capacity() + column_weight_.capacity()) +
           (float_engine_ ? float_engine_->bytes() : 0);
  }

  // out = conv(in) on this rank's slab (count x nx, row-major); in and out may be the same array. Collective.
  void apply(const Real* in, Real* out);

  // The same through callbacks, so that a caller's element-wise work rides in the transform's own passes
  // (as bem/convolution.hpp's producers and consumers): produce(r, row) writes the nx inputs of slab row r,
  // rows in order; multiplied(energy), when given, receives this rank's part of in . out = sum_q M |in_q|^2
  // (the spectral product, each stored column counted with its Hermitian partner) before the inverse
  // transform; consume(r, row) reads the nx outputs of slab row r, rows in order. Collective.
  using RowProducer = std::function<void(Index, Real*)>;
  using RowConsumer = std::function<void(Index, const Real*)>;
  void apply(const RowProducer& produce, const RowConsumer& consume,
             const std::function<void(double)>& multiplied = {});

 private:
  Slab slab_;
  MPI_Comm comm_;
  bool padded_;
  Index lx_, ly_;
  std::shared_ptr<DistributedRealFft2d> fft_;  // shared with another convolution or not; none with engine_
  SpectrumColumns2d spectrum_;
  std::vector<double> multiplier_;
  double self_response_ = 0;
  // Padded only: how the grid's rows travel to the transform's slabs (counts, offsets in values), and the
  // transform slab's grid rows in row order.
  std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
  // Padded only: the rows received (receive) and this rank's grid rows, produced or to be consumed
  // (padded_rows); shared with the transform.
  struct Buffers {
    std::vector<double> receive, padded_rows;
    std::vector<double> float_row;  // one rank in float: a row as produced and consumed
  };
  std::shared_ptr<Buffers> buffers_;
  std::vector<double> column_weight_;  // per spectral column: 1 or 2 (its Hermitian partner counted)
  // One rank on one thread: the serial engine (bem/convolution.hpp: rows, then columns a block at a time in
  // cache with the multiply between, no transpose), the same multiplier; FFTW-MPI's plan with its local
  // transposes then only makes the multiplier.
  std::unique_ptr<Convolution<double>> alone_;
  std::unique_ptr<Convolution<float>> alone_float_;  // the same in single precision (`single_precision`)
  // Two ranks and more, one thread a rank: the rows' spectra exchanged straight into column
  // blocks (mpi/slab_convolution_engine.hpp) instead of FFTW-MPI's pair; in double shared with `share` as
  // the transform is, in single precision its own.
  std::shared_ptr<SlabConvolutionEngine<double>> engine_;
  std::unique_ptr<SlabConvolutionEngine<float>> float_engine_;
};

}  // namespace contactbench::mpi
