// The convolution on slabs of rows (circular, or linear by zero padding) with one exchange each way and no
// global transpose of its own: what DistributedConvolution runs on two ranks and more, one thread a rank
// (docs/mpi.md "What a distributed iteration costs"). FFTW-MPI's pair moves each value through a local
// transpose, the global one and another local one each way, and multiplies in a pass of its own; here, as in
// the serial engine (bem/convolution.hpp), each rank transforms its rows and writes each row's spectrum
// straight into the send buffer's part for the rank that owns those columns; one MPI_Alltoallv leaves each
// rank its columns as an ny x columns block, row-major, which it transforms a few columns at a time in cache
// (along y, multiply, back: the serial engine's column blocks); the same block goes back by one
// MPI_Alltoallv, and each row is gathered from the parts as it is transformed back. In double, or in single
// precision (the serial filter's, bem/fourier_preconditioner.hpp; the solver's filter runs in double,
// docs/mpi.md says why): the rows produced are rounded to float before the transform, its output read as
// doubles.
#pragma once

#include <complex>
#include <functional>
#include <memory>
#include <vector>

#include <mpi.h>

#include "contactbench/core/types.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

// The two exchange buffers, raw bytes (FFTW's alignment): an engine's own, or shared by engines that never
// run at once (the solver's operator in double and its filter in float need the same values a point, the
// filter half the bytes).
class ExchangeStorage {
 public:
  ExchangeStorage(std::size_t by_destination_bytes, std::size_t my_block_bytes);
  ~ExchangeStorage();
  ExchangeStorage(const ExchangeStorage&) = delete;
  ExchangeStorage& operator=(const ExchangeStorage&) = delete;
  void* by_destination() const { return by_destination_; }
  void* my_block() const { return my_block_; }
  std::size_t by_destination_bytes() const { return by_destination_bytes_; }
  std::size_t my_block_bytes() const { return my_block_bytes_; }

 private:
  void* by_destination_ = nullptr;
  void* my_block_ = nullptr;
  std::size_t by_destination_bytes_ = 0, my_block_bytes_ = 0;
};

template <class T>
class SlabConvolutionEngine {
 public:
  // An nx x ny grid split in `slab`s (slab_of), its transform's lattice lx x ly: the grid itself (periodic,
  // circular) or 2 nx x 2 ny (zero padding, linear: the padding's rows are never stored or sent, as the
  // serial engine skips them). This rank's spectral columns are kx in [start, start + count) of the
  // lx/2 + 1, as every rank's are given in
  // `all_column_starts` / `all_column_counts` (rank order; FFTW-MPI's split, so that a multiplier made for
  // its transform serves here unchanged). Collective only in that every rank must make one.
  // `storage`: exchange buffers to use when they are large enough (another engine's, that never runs at
  // the same time as this one); else the engine makes its own.
  SlabConvolutionEngine(const Slab& slab, Index lx, Index ly, std::vector<Index> all_column_starts,
                        std::vector<Index> all_column_counts, MPI_Comm comm,
                        std::shared_ptr<ExchangeStorage> storage = nullptr);
  ~SlabConvolutionEngine();
  SlabConvolutionEngine(const SlabConvolutionEngine&) = delete;
  SlabConvolutionEngine& operator=(const SlabConvolutionEngine&) = delete;

  // Bytes it holds: the two exchange buffers (sizeof(T) a point of the slab each) unless they are another
  // engine's, and a few rows and columns.
  std::size_t bytes() const;
  const std::shared_ptr<ExchangeStorage>& storage() const { return storage_; }

  // out = IDFT(M . DFT(in)): produce(r, row) writes the nx inputs of slab row r (rows in order); M is this
  // rank's columns' multiplier (in T for the product), column c's ly values (ky) at multiplier[c * ly + ky],
  // even in ky, the pair's 1/(lx ly) folded in; column_weight[c] is 1 or 2 (the column's Hermitian partner
  // counted). multiplied(energy), when given, receives this rank's sum of weight M |in_q|^2 before the
  // transform back; consume(r, row) reads the nx outputs of slab row r (rows in order). Collective.
  void apply(const std::function<void(Index, Real*)>& produce,
             const std::function<void(Index, const Real*)>& consume, const std::vector<double>& multiplier,
             const std::vector<double>& column_weight, const std::function<void(double)>& multiplied);

 private:
  struct Plans;
  Slab slab_;
  MPI_Comm comm_;
  Index lx_, ly_, nxh_;
  std::vector<Index> column_starts_, column_counts_;
  Index my_columns_;
  // The rows' spectra by destination (this rank's rows x that rank's columns, row-major, in rank order),
  // and this rank's columns, ny x my_columns_ row-major (every rank's rows, in rank order).
  std::shared_ptr<ExchangeStorage> storage_;
  bool own_storage_ = true;
  std::complex<T>* by_destination_ = nullptr;
  std::complex<T>* my_block_ = nullptr;
  std::vector<int> row_counts_, row_offsets_, column_counts_values_, column_offsets_values_;
  // The rows as the caller produces and consumes them (double), and the transforms' scratch and plans.
  std::vector<double> caller_rows_;
  std::unique_ptr<Plans> plans_;
};

extern template class SlabConvolutionEngine<double>;
extern template class SlabConvolutionEngine<float>;

}  // namespace contactbench::mpi
