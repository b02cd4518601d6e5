#include "contactbench/mpi/distributed_convolution.hpp"

#include <algorithm>
#include <climits>
#include <complex>
#include <string>
#include <type_traits>
#include <vector>

#include "contactbench/core/error.hpp"
#include "contactbench/mpi/message_count.hpp"

namespace contactbench::mpi {

namespace {

// What the MPI counts of this file's exchanges are named by in an overflow error (mpi/message_count.hpp).
constexpr const char* kConvolutionExchange = "an exchange of the distributed convolution";

// How many rows two row ranges share, below `limit`.
Index shared_rows(Index start_a, Index count_a, Index start_b, Index count_b, Index limit) {
  return std::max<Index>(std::min({start_a + count_a, start_b + count_b, limit}) - std::max(start_a, start_b),
                         0);
}

// The serial engine (one rank, one thread) through the row callbacks. In float the rows produced in double
// are rounded as they enter and read back as doubles (as the float slab engine does, and the serial filter's
// own passes); `row` holds one row for that.
template <class T>
void apply_alone(Convolution<T>& convolution, std::vector<double>& row,
                 const DistributedConvolution::RowProducer& produce,
                 const DistributedConvolution::RowConsumer& consume,
                 const std::function<void(double)>& multiplied) {
  auto rows_in = [&](Index first, Index rows, T* buffer, Index ld, int) {
    for (Index i = 0; i < rows; ++i) {
      if constexpr (std::is_same_v<T, double>) {
        produce(first + i, buffer + i * ld);
      } else {
        produce(first + i, row.data());
        std::copy(row.begin(), row.end(), buffer + i * ld);
      }
    }
  };
  auto rows_out = [&](Index first, Index rows, const T* buffer, Index ld, int) {
    for (Index i = 0; i < rows; ++i) {
      if constexpr (std::is_same_v<T, double>) {
        consume(first + i, buffer + i * ld);
      } else {
        std::copy_n(buffer + i * ld, row.size(), row.begin());
        consume(first + i, row.data());
      }
    }
  };
  auto product = [&](double energy) { multiplied(energy); };
  if (multiplied)
    convolution.apply(rows_in, rows_out, {}, true, product);
  else
    convolution.apply(rows_in, rows_out);
}

}  // namespace

DistributedConvolution::DistributedConvolution(const Grid& grid, bool padded, MPI_Comm comm, int threads,
                                               const DistributedConvolution* share, bool single_precision)
    : slab_(slab_of(grid, comm)),
      comm_(comm),
      padded_(padded),
      lx_(padded ? 2 * grid.nx : grid.nx),
      ly_(padded ? 2 * grid.ny : grid.ny) {
  if (share && (share->padded_ != padded || share->lx_ != lx_ || share->ly_ != ly_ ||
                share->slab_.nx != slab_.nx || share->slab_.ny != slab_.ny))
    throw Error("mpi: a convolution can share the transform of one of the same grid and lattice only");
  // Two ranks and more, one thread a rank: the slab engine, with FFTW-MPI's split of the spectral columns
  // (so that the multipliers are made alike) but none of its transform (a padded operator makes one for
  // Love's kernel, transform(), and frees it once its multiplier is set).
  const bool slab_engine = size_of(comm) > 1 && threads <= 1;
  spectrum_ = spectrum_columns(lx_, ly_, comm);
  if (!slab_engine)
    fft_ =
        share && share->fft_ ? share->fft_ : std::make_shared<DistributedRealFft2d>(lx_, ly_, comm, threads);
  buffers_ = share ? share->buffers_ : std::make_shared<Buffers>();
  multiplier_.assign(static_cast<std::size_t>(spectrum_.count * ly_), 0.0);
  // Each stored column kx stands for +kx and -kx, except kx = 0 and the Nyquist column (even lx).
  for (Index c = 0; c < spectrum_.count; ++c) {
    const Index kx = spectrum_.start + c;
    column_weight_.push_back((kx == 0 || (lx_ % 2 == 0 && kx == lx_ / 2)) ? 1.0 : 2.0);
  }
  // One rank on one thread: the serial engine, in float where asked with the serial filter's estimated
  // plans (bem/fourier_preconditioner.hpp), so the same bits as the serial solver's filter.
  if (size_of(comm) == 1 && threads <= 1) {
    if (single_precision)
      alone_float_ = std::make_unique<Convolution<float>>(grid.nx, grid.ny, padded, 1, FftRigor::estimate);
    else
      alone_ = std::make_unique<Convolution<double>>(grid.nx, grid.ny, padded, 1);
  }
  if (slab_engine) {
    if (share && share->engine_ && !single_precision) {
      engine_ = share->engine_;
    } else {
      // Every rank's spectral columns.
      const Index mine[2] = {spectrum_.start, spectrum_.count};
      std::vector<Index> all(2 * static_cast<std::size_t>(size_of(comm)));
      MPI_Allgather(mine, 2, MPI_INT64_T, all.data(), 2, MPI_INT64_T, comm);
      std::vector<Index> starts, counts;
      for (std::size_t r = 0; r < all.size(); r += 2) {
        starts.push_back(all[r]);
        counts.push_back(all[r + 1]);
      }
      // The filter in float takes the operator's exchange buffers (`share`: never run at once).
      if (single_precision)
        float_engine_ = std::make_unique<SlabConvolutionEngine<float>>(
            slab_, lx_, ly_, std::move(starts), std::move(counts), comm,
            share && share->engine_ ? share->engine_->storage() : nullptr);
      else
        engine_ = std::make_shared<SlabConvolutionEngine<double>>(slab_, lx_, ly_, std::move(starts),
                                                                  std::move(counts), comm);
    }
  }
  if (!padded || slab_engine) return;
  buffers_->padded_rows.resize(static_cast<std::size_t>(std::max<Index>(slab_.points(), 1)));
  // The exchange plan: this rank's grid rows to the transform slabs that hold them. Both layouts are in rank
  // order, so what a rank sends (receives) is contiguous and in row order.
  const Index nx = grid.nx, ny = grid.ny;
  const auto grid_slabs = all_slabs(nx, ny, comm);
  const auto transform_slabs = all_slabs(lx_, ly_, comm);
  const Slab& mine = transform_slabs[static_cast<std::size_t>(rank_of(comm))];
  Index sent = 0, received = 0;
  for (std::size_t r = 0; r < grid_slabs.size(); ++r) {
    const Index out =
        shared_rows(slab_.start, slab_.count, transform_slabs[r].start, transform_slabs[r].count, ny);
    const Index in = shared_rows(grid_slabs[r].start, grid_slabs[r].count, mine.start, mine.count, ny);
    send_counts_.push_back(message_count(out * nx, kConvolutionExchange));
    send_offsets_.push_back(message_count(sent, kConvolutionExchange));
    receive_counts_.push_back(message_count(in * nx, kConvolutionExchange));
    receive_offsets_.push_back(message_count(received, kConvolutionExchange));
    sent += out * nx;
    received += in * nx;
  }
  buffers_->receive.resize(static_cast<std::size_t>(std::max<Index>(received, 1)));
}

DistributedConvolution::~DistributedConvolution() = default;

DistributedRealFft2d& DistributedConvolution::transform() {
  // On the slab engine, made when asked (Love's kernel, collectively) and freed by set_multiplier.
  if (!fft_) fft_ = std::make_shared<DistributedRealFft2d>(lx_, ly_, comm_, 1);
  return *fft_;
}

void DistributedConvolution::set_multiplier(std::vector<double> multiplier) {
  if (multiplier.size() != multiplier_.size())
    throw Error("mpi: the multiplier has " + std::to_string(multiplier.size()) + " values, this rank's " +
                std::to_string(spectrum_.count) + " spectral columns need " +
                std::to_string(multiplier_.size()));
  multiplier_ = std::move(multiplier);
  if (engine_ || float_engine_) fft_.reset();  // only made to transform a kernel
  double sum = 0;
  for (Index c = 0; c < spectrum_.count; ++c) {
    const double weight = column_weight_[static_cast<std::size_t>(c)];
    for (Index row = 0; row < ly_; ++row)
      sum += weight * multiplier_[static_cast<std::size_t>(c * ly_ + row)];
  }
  self_response_ = sum_over_ranks(sum, comm_);
  if (alone_ || alone_float_) {
    // The serial engine's layout: ly rows (ky) by lx / 2 + 1 columns (kx); here column-major by kx.
    const Index columns = spectrum_.count;
    Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m(ly_, columns);
    for (Index c = 0; c < columns; ++c)
      for (Index row = 0; row < ly_; ++row)
        m(row, c) = multiplier_[static_cast<std::size_t>(c * ly_ + row)];
    if (alone_) alone_->set_multiplier(m);
    if (alone_float_) alone_float_->set_multiplier(m);
  }
}

void DistributedConvolution::apply(const Real* in, Real* out) {
  const Index nx = slab_.nx;
  if (alone_) {
    alone_->apply(in, out);
    return;
  }
  if (!padded_ || engine_ || float_engine_ || alone_float_) {
    apply([&](Index r, Real* row) { std::copy_n(in + r * nx, nx, row); },
          [&](Index r, const Real* row) { std::copy_n(row, nx, out + r * nx); });
    return;
  }
  // Padded: the exchange straight from `in` and back into `out` (no copy through padded_rows_).
  const Slab& transform_slab = fft_->slab();
  const Index ny = slab_.ny;
  for (Index r = 0; r < transform_slab.count; ++r)
    std::fill_n(fft_->real_row(r), lx_, 0.0);
  MPI_Alltoallv(in, send_counts_.data(), send_offsets_.data(), MPI_DOUBLE, buffers_->receive.data(),
                receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE, comm_);
  const Index rows = shared_rows(0, ny, transform_slab.start, transform_slab.count, ny);
  for (Index r = 0; r < rows; ++r)
    std::copy_n(buffers_->receive.data() + r * nx, nx, fft_->real_row(r));
  fft_->forward();
  Complex* spectrum = fft_->spectrum();
  for (std::size_t i = 0; i < multiplier_.size(); ++i)
    spectrum[i] *= multiplier_[i];
  fft_->backward();
  for (Index r = 0; r < rows; ++r)
    std::copy_n(fft_->real_row(r), nx, buffers_->receive.data() + r * nx);
  MPI_Alltoallv(buffers_->receive.data(), receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE, out,
                send_counts_.data(), send_offsets_.data(), MPI_DOUBLE, comm_);
}

void DistributedConvolution::apply(const RowProducer& produce, const RowConsumer& consume,
                                   const std::function<void(double)>& multiplied) {
  if (alone_) {
    apply_alone(*alone_, buffers_->float_row, produce, consume, multiplied);
    return;
  }
  if (alone_float_) {
    buffers_->float_row.resize(static_cast<std::size_t>(slab_.nx));
    apply_alone(*alone_float_, buffers_->float_row, produce, consume, multiplied);
    return;
  }
  if (engine_) {
    engine_->apply(produce, consume, multiplier_, column_weight_, multiplied);
    return;
  }
  if (float_engine_) {
    float_engine_->apply(produce, consume, multiplier_, column_weight_, multiplied);
    return;
  }
  const Slab& transform_slab = fft_->slab();
  const Index nx = slab_.nx, ny = slab_.ny;
  if (!padded_) {
    for (Index r = 0; r < slab_.count; ++r)
      produce(r, fft_->real_row(r));
  } else {
    // The transform's slab cleared (the last inverse wrote all of it: that is the zero padding), then the
    // grid rows it owns arrive from their ranks.
    for (Index r = 0; r < slab_.count; ++r)
      produce(r, buffers_->padded_rows.data() + r * nx);
    for (Index r = 0; r < transform_slab.count; ++r)
      std::fill_n(fft_->real_row(r), lx_, 0.0);
    MPI_Alltoallv(buffers_->padded_rows.data(), send_counts_.data(), send_offsets_.data(), MPI_DOUBLE,
                  buffers_->receive.data(), receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE,
                  comm_);
    const Index rows = shared_rows(0, ny, transform_slab.start, transform_slab.count, ny);
    for (Index r = 0; r < rows; ++r)
      std::copy_n(buffers_->receive.data() + r * nx, nx, fft_->real_row(r));
  }
  fft_->forward();
  Complex* spectrum = fft_->spectrum();
  if (multiplied) {
    // The product from the spectrum (Parseval; M carries the pair's 1/(lx ly)), made in the multiply's pass.
    double energy = 0;
    for (Index c = 0; c < fft_->spectrum_count(); ++c) {
      double column = 0;
      Complex* values = spectrum + c * ly_;
      const double* m = multiplier_.data() + c * ly_;
      for (Index row = 0; row < ly_; ++row) {
        column += m[row] * std::norm(values[row]);
        values[row] *= m[row];
      }
      energy += column_weight_[static_cast<std::size_t>(c)] * column;
    }
    multiplied(energy);
  } else {
    for (std::size_t i = 0; i < multiplier_.size(); ++i)
      spectrum[i] *= multiplier_[i];
  }
  fft_->backward();
  if (!padded_) {
    for (Index r = 0; r < slab_.count; ++r)
      consume(r, fft_->real_row(r));
  } else {
    const Index rows = shared_rows(0, ny, transform_slab.start, transform_slab.count, ny);
    for (Index r = 0; r < rows; ++r)
      std::copy_n(fft_->real_row(r), nx, buffers_->receive.data() + r * nx);
    // The reverse exchange: what was received goes back where it came from.
    MPI_Alltoallv(buffers_->receive.data(), receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE,
                  buffers_->padded_rows.data(), send_counts_.data(), send_offsets_.data(), MPI_DOUBLE, comm_);
    for (Index r = 0; r < slab_.count; ++r)
      consume(r, buffers_->padded_rows.data() + r * nx);
  }
}

}  // namespace contactbench::mpi
