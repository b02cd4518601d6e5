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
template <class T>
constexpr Index kValuesPerLine = 64 / static_cast<Index>(sizeof(std::complex<T>));

// The row stride of a run of `width` spectral values: whole cache lines, an odd number of them. A column
// block reads one line from each of ny rows; with a stride of a power of two lines (a rank's 1024 columns of
// a 4096 grid: 16 KiB) those rows all fall in a few of the cache's sets and evict each other, which made the
// rank with such a run ~10 % slower than the other at every size (perf: the engine's own loop 23 % of its
// time against 14 %); an odd number of lines spreads them over every set.
template <class T>
Index run_stride(Index width) {
  const Index lines = (width + kValuesPerLine<T> - 1) / kValuesPerLine<T>;
  return (lines % 2 == 0 ? lines + 1 : lines) * kValuesPerLine<T>;
}

// A column of `length` spectral values times its multiplier m (in double, rounded to T as the serial
// engine's multiplier is), conjugated for the transform back (see apply); with `energy`, returns sum m |c|^2
// before the product. The serial engine's multiply_column (bem/convolution.cpp: re and im in simd loops over
// the values) on a multiplier of all ly values, since a padded operator's (Love's kernel transformed) is
// even only to round-off.
template <class T>
double multiply_conjugated(std::complex<T>* column, const double* __restrict m, Index length, bool energy) {
  T* __restrict c = reinterpret_cast<T*>(column);
  double sum = 0;
  if (energy) {
#pragma omp simd reduction(+ : sum)
    for (Index k = 0; k < length; ++k) {
      const T re = c[2 * k], im = c[2 * k + 1];
      sum += static_cast<double>(static_cast<T>(m[k])) *
             (static_cast<double>(re) * re + static_cast<double>(im) * im);
    }
  }
#pragma omp simd
  for (Index k = 0; k < length; ++k) {
    const T mk = static_cast<T>(m[k]);
    c[2 * k] *= mk;
    c[2 * k + 1] *= -mk;
  }
  return sum;
}

// MPI's type of a transform's real values.
template <class T>
MPI_Datatype mpi_type_of() {
  return std::is_same_v<T, double> ? MPI_DOUBLE : MPI_FLOAT;
}

}  // namespace

// Estimated plans, as FFTW-MPI's here: the same plan on every run, so the same round-off.
template <class T>
struct SlabConvolutionEngine<T>::Plans {
  using F = Fftw<T>;
  static constexpr Index kColumnsPerBlock = kValuesPerLine<T>;
  T* rows = nullptr;                      // a chunk of rows, in T, as transformed (zero beyond nx)
  T* rows_out = nullptr;                  // a chunk of rows transformed back (all lx values)
  typename F::Cx* row_spectra = nullptr;  // to plan their spectra on (they are written into the rows' part)
  typename F::Cx* columns = nullptr;      // a block of columns, each contiguous
  typename F::Plan r2c_full = nullptr, r2c_rest = nullptr, c2r_full = nullptr, c2r_rest = nullptr;
  typename F::Plan columns_forward = nullptr;

  // Rows of lx values (the grid's nx, then zeros when padded), their spectra `row_stride` apart; columns of
  // ly.
  Plans(Index lx, Index ly, Index row_stride, Index slab_rows) {
    const Index nx = lx, ny = ly;  // the transforms' lengths
    rows = static_cast<T*>(F::malloc(sizeof(T) * static_cast<std::size_t>(kRowsPerChunk * nx)));
    rows_out = static_cast<T*>(F::malloc(sizeof(T) * static_cast<std::size_t>(kRowsPerChunk * nx)));
    row_spectra = static_cast<typename F::Cx*>(
        F::malloc(sizeof(typename F::Cx) * static_cast<std::size_t>(kRowsPerChunk * row_stride)));
    columns = static_cast<typename F::Cx*>(
        F::malloc(sizeof(typename F::Cx) * static_cast<std::size_t>(kColumnsPerBlock * ny)));
    if (!rows || !rows_out || !row_spectra || !columns)
      throw Error("mpi: out of memory for the slab convolution's buffers");
    const int n_x = static_cast<int>(nx), n_y = static_cast<int>(ny), stride = static_cast<int>(row_stride);
    const int rest = static_cast<int>(slab_rows % kRowsPerChunk);
    auto lock = lock_fftw_planner();
    F::plan_with_nthreads(1);
    std::fill(rows, rows + kRowsPerChunk * nx, T(0));  // the padding stays zero: rows are produced nx long
    const int full = static_cast<int>(kRowsPerChunk);
    r2c_full = F::r2c(n_x, full, rows, n_x, row_spectra, stride, FFTW_ESTIMATE);
    c2r_full = F::c2r(n_x, full, row_spectra, stride, rows_out, n_x, FFTW_ESTIMATE);
    if (rest > 0) {
      r2c_rest = F::r2c(n_x, rest, rows, n_x, row_spectra, stride, FFTW_ESTIMATE);
      c2r_rest = F::c2r(n_x, rest, row_spectra, stride, rows_out, n_x, FFTW_ESTIMATE);
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
      my_columns_(column_counts_.at(static_cast<std::size_t>(rank_of(comm)))),
      my_stride_(run_stride<T>(my_columns_)),
      row_stride_(run_stride<T>(nxh_)) {
  slabs_ = all_slabs(slab.nx, slab.ny, comm);
  const auto& slabs = slabs_;
  const Index rows_bytes = static_cast<Index>(sizeof(std::complex<T>)) * slab.count * row_stride_;
  Index block_values = 0;
  for (const Slab& other : slabs)
    block_values += other.count * my_stride_;
  const auto to_bytes = static_cast<std::size_t>(rows_bytes),
             from_bytes = sizeof(std::complex<T>) * static_cast<std::size_t>(block_values);
  // Every rank decides alike (the shared window is made by all or none).
  int fits = storage && storage->fits(to_bytes, from_bytes) ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &fits, 1, MPI_INT, MPI_LAND, comm);
  own_storage_ = fits == 0;
  storage_ = own_storage_ ? std::make_shared<ExchangeStorage>(comm, choose_exchange_transport(comm, to_bytes),
                                                              to_bytes, from_bytes)
                          : std::move(storage);
  rows_ = static_cast<std::complex<T>*>(storage_->rows());
  my_block_ = static_cast<std::complex<T>*>(storage_->block());
  const bool shared = storage_->transport() == ExchangeTransport::shared_memory;
  // Where rank s's rows of this rank's columns are, my_columns_ values a row: in shared memory in rank s's
  // own part, from this rank's first column on, row_stride_ apart; by messages in this rank's block, after
  // the earlier ranks' rows, my_stride_ apart.
  column_stride_ = shared ? row_stride_ : my_stride_;
  const Index my_start = column_starts_.at(static_cast<std::size_t>(rank_of(comm)));
  // In shared memory this rank's first column lies where its run starts in the rows (kx = my_start), not
  // always at a cache line; the first block is cut short to the next line, so that every later block reads
  // one line a row, not two.
  const Index per_line = Plans::kColumnsPerBlock;
  first_block_ = shared && my_start % per_line != 0 ? per_line - my_start % per_line : per_line;
  Index received = 0;
  for (std::size_t s = 0; s < slabs.size(); ++s) {
    column_sources_.push_back(shared ? static_cast<std::complex<T>*>(storage_->segment(static_cast<int>(s))) +
                                           my_start
                                     : my_block_ + received);
    received += slabs[s].count * my_stride_;
  }
  if (!shared) make_message_types();
  // The strides' spare values may travel (the runs' padding): zero, not whatever the allocation held.
  std::fill_n(rows_, slab.count * row_stride_, std::complex<T>(0));
  if (!shared) std::fill_n(my_block_, block_values, std::complex<T>(0));
  if constexpr (!std::is_same_v<T, double>)
    caller_rows_.resize(static_cast<std::size_t>(kRowsPerChunk * slab.nx));
  plans_ = std::make_unique<Plans>(lx, ly, row_stride_, slab.count);
}

// By messages, each exchange's runs described in place (MPI_Alltoallw's derived types), so that neither side
// copies them into a buffer of its own: to rank r, this rank's rows of r's columns, a vector of slab rows of
// 2 width_r values row_stride_ apart, from r's first column; from rank s, s's rows of this rank's columns
// into this rank's block, my_stride_ apart. Each type carries its own byte offset (MPI_Alltoallw's
// displacements are int bytes, which a rank's block beyond 2 GiB would overflow), the displacements 0.
template <class T>
void SlabConvolutionEngine<T>::make_message_types() {
  const MPI_Datatype value = mpi_type_of<T>();
  const auto cx = static_cast<MPI_Aint>(sizeof(std::complex<T>));
  const auto placed = [](MPI_Datatype inner, MPI_Aint offset) {
    int one = 1;
    MPI_Datatype type = MPI_DATATYPE_NULL;
    MPI_Type_create_struct(1, &one, &offset, &inner, &type);
    MPI_Type_commit(&type);
    MPI_Type_free(&inner);
    return type;
  };
  Index received = 0;
  for (std::size_t r = 0; r < slabs_.size(); ++r) {
    MPI_Datatype to_r = MPI_DATATYPE_NULL, from_r = MPI_DATATYPE_NULL;
    MPI_Type_vector(message_count(slab_.count, kEngineExchange),
                    message_count(2 * column_counts_[r], kEngineExchange),
                    message_count(2 * row_stride_, kEngineExchange), value, &to_r);
    MPI_Type_vector(message_count(slabs_[r].count, kEngineExchange),
                    message_count(2 * my_columns_, kEngineExchange),
                    message_count(2 * my_stride_, kEngineExchange), value, &from_r);
    row_types_.push_back(placed(to_r, cx * static_cast<MPI_Aint>(column_starts_[r])));
    block_types_.push_back(placed(from_r, cx * static_cast<MPI_Aint>(received)));
    ones_.push_back(1);
    zeros_.push_back(0);
    received += slabs_[r].count * my_stride_;
  }
}

template <class T>
SlabConvolutionEngine<T>::~SlabConvolutionEngine() {
  for (auto* types : {&row_types_, &block_types_})
    for (MPI_Datatype& type : *types)
      MPI_Type_free(&type);
}

template <class T>
std::size_t SlabConvolutionEngine<T>::bytes() const {
  return (own_storage_ ? storage_->bytes() : 0) + sizeof(double) * caller_rows_.capacity() +
         sizeof(T) * static_cast<std::size_t>(2 * kRowsPerChunk * lx_) +
         sizeof(std::complex<T>) *
             static_cast<std::size_t>(kRowsPerChunk * row_stride_ + Plans::kColumnsPerBlock * ly_);
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
  const Index nx = slab_.nx, ny = slab_.ny, lx = lx_, ly = ly_;
  auto* columns = reinterpret_cast<Cx*>(plans.columns);
  double* caller = caller_rows_.data();
  const bool shared = storage_->transport() == ExchangeTransport::shared_memory;
  const auto exchange = [&](bool to_columns) {
    if (shared) {
      storage_->synchronise();
      return;
    }
    void* rows = rows_;
    void* block = my_block_;
    if (to_columns)
      MPI_Alltoallw(rows, ones_.data(), zeros_.data(), row_types_.data(), block, ones_.data(), zeros_.data(),
                    block_types_.data(), comm_);
    else
      MPI_Alltoallw(block, ones_.data(), zeros_.data(), block_types_.data(), rows, ones_.data(),
                    zeros_.data(), row_types_.data(), comm_);
  };

  // 1. Rows: produced, transformed along x, each row's spectrum written in place in this rank's rows.
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
    F::execute_r2c(rows == kRowsPerChunk ? plans.r2c_full : plans.r2c_rest, plans.rows,
                   reinterpret_cast<typename F::Cx*>(rows_ + first * row_stride_));
  }
  exchange(true);

  // 2. This rank's columns, a block at a time in cache: along y, multiply, back (the transform back is the
  //    forward one between two conjugations, as in the serial engine: one plan); row y of the block is
  //    row y - start of its owner's, column_sources_[owner].
  const auto each_row = [&](auto&& visit) {
    for (std::size_t s = 0; s < slabs_.size(); ++s)
      for (Index i = 0; i < slabs_[s].count; ++i)
        visit(slabs_[s].start + i, column_sources_[s] + i * column_stride_);
  };
  double energy = 0;
  const bool want_energy = static_cast<bool>(multiplied);
  for (Index c0 = 0, width = 0; c0 < my_columns_; c0 += width) {
    width = std::min(c0 == 0 ? first_block_ : B, my_columns_ - c0);
    const bool next_block = c0 + width < my_columns_;
    each_row([&](Index y, const Cx* row) {
      // The next block's line of this row, asked for now: it arrives while this block is transformed. Rows
      // lie a few KiB apart, beyond what the hardware's stride prefetcher follows, so without it every line
      // of a block is a wait (perf: most of this loop's time).
      if (next_block) __builtin_prefetch(row + c0 + width, 0, 3);
      for (Index j = 0; j < width; ++j)
        columns[j * ly + y] = row[c0 + j];
    });
    for (Index j = 0; j < width; ++j)  // the padding's rows (none when periodic)
      std::fill(columns + j * ly + ny, columns + (j + 1) * ly, Cx(0));
    if (width < B) std::fill(columns + width * ly, columns + B * ly, Cx(0));
    F::execute_c2c(plans.columns_forward, plans.columns);
    for (Index j = 0; j < width; ++j) {
      const double sum =
          multiply_conjugated(columns + j * ly, multiplier.data() + (c0 + j) * ly, ly, want_energy);
      energy += column_weight[static_cast<std::size_t>(c0 + j)] * sum;
    }
    F::execute_c2c(plans.columns_forward, plans.columns);
    each_row([&](Index y, Cx* row) {
      for (Index j = 0; j < width; ++j)
        row[c0 + j] = std::conj(columns[j * ly + y]);
    });
  }
  if (multiplied) multiplied(energy);

  // 3. Back: each rank's rows of this rank's columns to it (in shared memory they are in its rows already);
  //    each row transformed back along x from where it lies.
  exchange(false);
  for (Index first = 0; first < slab_.count; first += kRowsPerChunk) {
    const Index rows = std::min(kRowsPerChunk, slab_.count - first);
    F::execute_c2r(rows == kRowsPerChunk ? plans.c2r_full : plans.c2r_rest,
                   reinterpret_cast<typename F::Cx*>(rows_ + first * row_stride_), plans.rows_out);
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
