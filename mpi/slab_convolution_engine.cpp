#include "contactbench/mpi/slab_convolution_engine.hpp"

#include <algorithm>
#include <complex>
#include <string>
#include <type_traits>

#include <fftw3.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/core/fftw_precision.hpp"
#include "contactbench/mpi/message_count.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchanges are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kEngineExchange = "an exchange of the slab convolution";

// Rows per transform call and a block of columns of 64 bytes a row, as the serial engine's
// (bem/convolution.cpp): a chunk of rows in L2, a block of columns one cache line of each row.
constexpr Index kRowsPerChunk = 8;

// MPI's type of a transform's real values.
template <class T>
MPI_Datatype mpi_type_of() {
  return std::is_same_v<T, double> ? MPI_DOUBLE : MPI_FLOAT;
}

}  // namespace

ExchangeStorage::ExchangeStorage(std::size_t by_destination_bytes, std::size_t my_block_bytes)
    : by_destination_(fftw_malloc(std::max<std::size_t>(by_destination_bytes, 16))),
      my_block_(fftw_malloc(std::max<std::size_t>(my_block_bytes, 16))),
      by_destination_bytes_(by_destination_bytes),
      my_block_bytes_(my_block_bytes) {
  if (!by_destination_ || !my_block_) {
    fftw_free(by_destination_);
    fftw_free(my_block_);
    throw Error("mpi: out of memory for the slab convolution's exchange buffers");
  }
}

ExchangeStorage::~ExchangeStorage() {
  fftw_free(by_destination_);
  fftw_free(my_block_);
}

// Estimated plans, as FFTW-MPI's here: the same plan on every run, so the same round-off.
template <class T>
struct SlabConvolutionEngine<T>::Plans {
  using F = Fftw<T>;
  static constexpr Index kColumnsPerBlock = 64 / static_cast<Index>(sizeof(std::complex<T>));
  T* rows = nullptr;                      // a chunk of rows, in T, as transformed (zero beyond nx)
  T* rows_out = nullptr;                  // a chunk of rows transformed back (all lx values)
  typename F::Cx* row_spectra = nullptr;  // their spectra
  typename F::Cx* columns = nullptr;      // a block of columns, each contiguous
  typename F::Plan r2c_full = nullptr, r2c_rest = nullptr, c2r_full = nullptr, c2r_rest = nullptr;
  typename F::Plan columns_forward = nullptr;

  // Rows of lx values (the grid's nx, then zeros when padded), columns of ly.
  Plans(Index lx, Index ly, Index nxh, Index slab_rows) {
    const Index nx = lx, ny = ly;  // the transforms' lengths
    rows = static_cast<T*>(F::malloc(sizeof(T) * static_cast<std::size_t>(kRowsPerChunk * nx)));
    rows_out = static_cast<T*>(F::malloc(sizeof(T) * static_cast<std::size_t>(kRowsPerChunk * nx)));
    row_spectra = static_cast<typename F::Cx*>(
        F::malloc(sizeof(typename F::Cx) * static_cast<std::size_t>(kRowsPerChunk * nxh)));
    columns = static_cast<typename F::Cx*>(
        F::malloc(sizeof(typename F::Cx) * static_cast<std::size_t>(kColumnsPerBlock * ny)));
    if (!rows || !rows_out || !row_spectra || !columns)
      throw Error("mpi: out of memory for the slab convolution's buffers");
    const int n_x = static_cast<int>(nx), n_y = static_cast<int>(ny), n_xh = static_cast<int>(nxh);
    const int rest = static_cast<int>(slab_rows % kRowsPerChunk);
    auto lock = lock_fftw_planner();
    F::plan_with_nthreads(1);
    std::fill(rows, rows + kRowsPerChunk * nx, T(0));  // the padding stays zero: rows are produced nx long
    const int full = static_cast<int>(kRowsPerChunk);
    r2c_full = F::r2c(n_x, full, rows, n_x, row_spectra, n_xh, FFTW_ESTIMATE);
    c2r_full = F::c2r(n_x, full, row_spectra, n_xh, rows_out, n_x, FFTW_ESTIMATE);
    if (rest > 0) {
      r2c_rest = F::r2c(n_x, rest, rows, n_x, row_spectra, n_xh, FFTW_ESTIMATE);
      c2r_rest = F::c2r(n_x, rest, row_spectra, n_xh, rows_out, n_x, FFTW_ESTIMATE);
    }
    columns_forward = F::c2c(n_y, static_cast<int>(kColumnsPerBlock), columns, FFTW_FORWARD, FFTW_ESTIMATE);
    if (!r2c_full || !c2r_full || !columns_forward || (rest > 0 && (!r2c_rest || !c2r_rest)))
      throw Error("mpi: FFTW could not plan the slab convolution's transforms");
  }
  ~Plans() {
    {
      auto lock = lock_fftw_planner();
      for (auto p : {r2c_full, r2c_rest, c2r_full, c2r_rest, columns_forward})
        F::destroy(p);
    }
    F::free(rows);
    F::free(rows_out);
    F::free(row_spectra);
    F::free(columns);
  }
  Plans(const Plans&) = delete;
  Plans& operator=(const Plans&) = delete;
};

template <class T>
SlabConvolutionEngine<T>::SlabConvolutionEngine(const Slab& slab, Index lx, Index ly,
                                                std::vector<Index> all_column_starts,
                                                std::vector<Index> all_column_counts, MPI_Comm comm,
                                                std::shared_ptr<ExchangeStorage> storage)
    : slab_(slab),
      comm_(comm),
      lx_(lx),
      ly_(ly),
      nxh_(lx / 2 + 1),
      column_starts_(std::move(all_column_starts)),
      column_counts_(std::move(all_column_counts)),
      my_columns_(column_counts_.at(static_cast<std::size_t>(rank_of(comm)))) {
  const auto slabs = all_slabs(slab.nx, slab.ny, comm);
  Index to = 0, from = 0;
  for (std::size_t r = 0; r < slabs.size(); ++r) {
    // Forward: this rank's rows of rank r's columns out; rank r's rows of this rank's columns in (counts in
    // T values: two a complex value).
    row_offsets_.push_back(message_count(2 * to, kEngineExchange));
    row_counts_.push_back(message_count(2 * slab.count * column_counts_[r], kEngineExchange));
    column_offsets_values_.push_back(message_count(2 * from, kEngineExchange));
    column_counts_values_.push_back(message_count(2 * slabs[r].count * my_columns_, kEngineExchange));
    to += slab.count * column_counts_[r];
    from += slabs[r].count * my_columns_;
  }
  const std::size_t to_bytes = sizeof(std::complex<T>) * static_cast<std::size_t>(to),
                    from_bytes = sizeof(std::complex<T>) * static_cast<std::size_t>(from);
  own_storage_ =
      !storage || storage->by_destination_bytes() < to_bytes || storage->my_block_bytes() < from_bytes;
  storage_ = own_storage_ ? std::make_shared<ExchangeStorage>(to_bytes, from_bytes) : std::move(storage);
  by_destination_ = static_cast<std::complex<T>*>(storage_->by_destination());
  my_block_ = static_cast<std::complex<T>*>(storage_->my_block());
  if constexpr (!std::is_same_v<T, double>)
    caller_rows_.resize(static_cast<std::size_t>(kRowsPerChunk * slab.nx));
  plans_ = std::make_unique<Plans>(lx, ly, nxh_, slab.count);
}

template <class T>
SlabConvolutionEngine<T>::~SlabConvolutionEngine() = default;

template <class T>
std::size_t SlabConvolutionEngine<T>::bytes() const {
  return (own_storage_ ? storage_->by_destination_bytes() + storage_->my_block_bytes() : 0) +
         sizeof(double) * caller_rows_.capacity() +
         sizeof(T) * static_cast<std::size_t>(2 * kRowsPerChunk * lx_) +
         sizeof(std::complex<T>) *
             static_cast<std::size_t>(kRowsPerChunk * nxh_ + Plans::kColumnsPerBlock * ly_);
}

template <class T>
void SlabConvolutionEngine<T>::apply(const std::function<void(Index, Real*)>& produce,
                                     const std::function<void(Index, const Real*)>& consume,
                                     const std::vector<double>& multiplier,
                                     const std::vector<double>& column_weight,
                                     const std::function<void(double)>& multiplied) {
  using F = Fftw<T>;
  using Cx = std::complex<T>;
  constexpr Index B = Plans::kColumnsPerBlock;
  Plans& plans = *plans_;
  const Index nx = slab_.nx, ny = slab_.ny, lx = lx_, ly = ly_,
              ranks = static_cast<Index>(column_counts_.size());
  auto* spectra = reinterpret_cast<Cx*>(plans.row_spectra);
  auto* columns = reinterpret_cast<Cx*>(plans.columns);
  double* caller = caller_rows_.data();
  const MPI_Datatype type = mpi_type_of<T>();

  // 1. Rows: produced, transformed along x, each row's spectrum cut into the destinations' column runs.
  for (Index first = 0; first < slab_.count; first += kRowsPerChunk) {
    const Index rows = std::min(kRowsPerChunk, slab_.count - first);
    for (Index i = 0; i < rows; ++i) {
      if constexpr (std::is_same_v<T, double>) {
        produce(first + i, plans.rows + i * lx);
      } else {
        produce(first + i, caller);
        for (Index x = 0; x < nx; ++x)
          plans.rows[i * lx + x] = static_cast<T>(caller[x]);
      }
    }
    F::execute_r2c(rows == kRowsPerChunk ? plans.r2c_full : plans.r2c_rest, plans.rows, plans.row_spectra);
    Cx* part = by_destination_;
    for (Index r = 0; r < ranks; ++r) {
      const Index width = column_counts_[static_cast<std::size_t>(r)];
      const Index start = column_starts_[static_cast<std::size_t>(r)];
      for (Index i = 0; i < rows; ++i)
        std::copy_n(spectra + i * nxh_ + start, width, part + (first + i) * width);
      part += slab_.count * width;
    }
  }
  MPI_Alltoallv(by_destination_, row_counts_.data(), row_offsets_.data(), type, my_block_,
                column_counts_values_.data(), column_offsets_values_.data(), type, comm_);

  // 2. This rank's columns, a block at a time in cache: along y, multiply, back (the transform back is the
  //    forward one between two conjugations, as in the serial engine: one plan).
  double energy = 0;
  for (Index c0 = 0; c0 < my_columns_; c0 += B) {
    const Index width = std::min(B, my_columns_ - c0);
    for (Index y = 0; y < ny; ++y)
      for (Index j = 0; j < width; ++j)
        columns[j * ly + y] = my_block_[static_cast<std::size_t>(y * my_columns_ + c0 + j)];
    for (Index j = 0; j < width; ++j)  // the padding's rows (none when periodic)
      std::fill(columns + j * ly + ny, columns + (j + 1) * ly, Cx(0));
    if (width < B) std::fill(columns + width * ly, columns + B * ly, Cx(0));
    F::execute_c2c(plans.columns_forward, plans.columns);
    for (Index j = 0; j < width; ++j) {
      Cx* column = columns + j * ly;
      const double* m = multiplier.data() + (c0 + j) * ly;
      double sum = 0;
      for (Index k = 0; k < ly; ++k) {
        const T mk = static_cast<T>(m[k]);
        sum += static_cast<double>(mk) * std::norm(std::complex<double>(column[k]));
        column[k] = std::conj(column[k] * mk);
      }
      energy += column_weight[static_cast<std::size_t>(c0 + j)] * sum;
    }
    F::execute_c2c(plans.columns_forward, plans.columns);
    for (Index y = 0; y < ny; ++y)
      for (Index j = 0; j < width; ++j)
        my_block_[static_cast<std::size_t>(y * my_columns_ + c0 + j)] = std::conj(columns[j * ly + y]);
  }
  if (multiplied) multiplied(energy);

  // 3. Back: each rank's rows of this rank's columns to it; each row gathered from its column runs and
  //    transformed back along x.
  MPI_Alltoallv(my_block_, column_counts_values_.data(), column_offsets_values_.data(), type, by_destination_,
                row_counts_.data(), row_offsets_.data(), type, comm_);
  for (Index first = 0; first < slab_.count; first += kRowsPerChunk) {
    const Index rows = std::min(kRowsPerChunk, slab_.count - first);
    const Cx* part = by_destination_;
    for (Index r = 0; r < ranks; ++r) {
      const Index width = column_counts_[static_cast<std::size_t>(r)];
      const Index start = column_starts_[static_cast<std::size_t>(r)];
      for (Index i = 0; i < rows; ++i)
        std::copy_n(part + (first + i) * width, width, spectra + i * nxh_ + start);
      part += slab_.count * width;
    }
    F::execute_c2r(rows == kRowsPerChunk ? plans.c2r_full : plans.c2r_rest, plans.row_spectra,
                   plans.rows_out);
    for (Index i = 0; i < rows; ++i) {
      if constexpr (std::is_same_v<T, double>) {
        consume(first + i, plans.rows_out + i * lx);
      } else {
        for (Index x = 0; x < nx; ++x)
          caller[x] = static_cast<double>(plans.rows_out[i * lx + x]);
        consume(first + i, caller);
      }
    }
  }
}

template class SlabConvolutionEngine<double>;
template class SlabConvolutionEngine<float>;

}  // namespace contactbench::mpi
