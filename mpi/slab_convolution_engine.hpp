// The convolution on slabs of rows (circular, or linear by zero padding) with one exchange each way and no
// global transpose of its own: what DistributedConvolution runs on two ranks and more, one thread a rank
// (docs/mpi.md "What a distributed iteration costs"). FFTW-MPI's pair moves each value through a local
// transpose, the global one and another local one each way, and multiplies in a pass of its own; here, as in
// the serial engine (bem/convolution.hpp), each rank transforms its rows, their spectra written in place in
// its rows' buffer; each rank transforms its columns of every rank's rows a few columns at a time in cache
// (along y, multiply, back: the serial engine's column blocks), and each rank transforms its rows back from
// where they lie. Between the passes the columns reach their owner and come back: on one machine they are
// read and written in place in memory the ranks share (mpi/exchange_storage.hpp), between two barriers, and
// nothing is copied; otherwise one MPI_Alltoallw each way, whose derived types pick each rank's runs out of
// the rows and into its ny x columns block. The same arithmetic either way, so the same bits.
// In double, or in single precision (the serial filter's, bem/fourier_preconditioner.hpp, and so the
// distributed solver's filter): the rows produced are rounded to float before the transform, its
// output read as doubles.
#pragma once

#include <complex>
#include <functional>
#include <memory>
#include <vector>

#include <mpi.h>

#include "contactbench/core/types.hpp"
#include "contactbench/mpi/exchange_storage.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

template <class T>
class SlabConvolutionEngine {
 public:
  // An nx x ny grid split in `slab`s (slab_of), its transform's lattice lx x ly: the grid itself (periodic,
  // circular) or 2 nx x 2 ny (zero padding, linear: the padding's rows are never stored or sent, as the
  // serial engine skips them). This rank's spectral columns are kx in [start, start + count) of the
  // lx/2 + 1, as every rank's are given in
  // `all_column_starts` / `all_column_counts` (rank order; FFTW-MPI's split, so that a multiplier made for
  // its transform serves here unchanged). Collective only in that every rank must make one.
  // `storage`: exchange buffers to use when they are large enough on every rank (another engine's, that
  // never runs at the same time as this one); else the engine makes its own, with the transport
  // choose_exchange_transport gives.
  SlabConvolutionEngine(const Slab& slab, Index lx, Index ly, std::vector<Index> all_column_starts,
                        std::vector<Index> all_column_counts, MPI_Comm comm,
                        std::shared_ptr<ExchangeStorage> storage = nullptr);
  ~SlabConvolutionEngine();
  SlabConvolutionEngine(const SlabConvolutionEngine&) = delete;
  SlabConvolutionEngine& operator=(const SlabConvolutionEngine&) = delete;

  // Bytes it holds: the exchange buffers (two of sizeof(T) a point of the slab by messages, one in shared
  // memory) unless they are another engine's, and a few rows and columns.
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
  Index lx_, ly_, nxh_;  // the lattice, and its half spectrum's columns
  std::vector<Index> column_starts_, column_counts_;
  Index my_columns_;
  // This rank's columns are read in rows of my_stride_ values by messages (its block), of row_stride_ in
  // shared memory (the rows' owners' parts): whole cache lines, an odd number of them (run_stride in the
  // .cpp says why).
  Index my_stride_, row_stride_, column_stride_ = 0;
  Index first_block_ = 0;  // columns in the first column block (the constructor says why it may be short)
  // This rank's rows' spectra, row_stride_ apart (by messages its buffer, in shared memory its part of the
  // window), and by messages this rank's columns of every rank's rows, ny x my_columns_ (my_stride_ apart,
  // in rank order); rank s's rows of this rank's columns at column_sources_[s], column_stride_ apart.
  std::shared_ptr<ExchangeStorage> storage_;
  bool own_storage_ = true;
  std::complex<T>* rows_ = nullptr;
  std::complex<T>* my_block_ = nullptr;
  std::vector<std::complex<T>*> column_sources_;
  std::vector<Slab> slabs_;
  // By messages: MPI_Alltoallw's description of the runs in place (make_message_types).
  void make_message_types();
  std::vector<MPI_Datatype> row_types_, block_types_;
  std::vector<int> ones_, zeros_;  // the counts and displacements (in the types) of every rank's part
  // The rows as the caller produces and consumes them (double), and the transforms' scratch and plans.
  std::vector<double> caller_rows_;
  std::unique_ptr<Plans> plans_;
};

extern template class SlabConvolutionEngine<double>;
extern template class SlabConvolutionEngine<float>;

}  // namespace contactbench::mpi
