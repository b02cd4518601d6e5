#include "contactbench/mpi/distributed_half_space.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "contactbench/bem/love_kernel.hpp"
#include "contactbench/core/error.hpp"
#include "contactbench/core/spectrum.hpp"

namespace contactbench::mpi {

namespace {

int checked_int(Index values) {
  if (values > INT_MAX) throw Error("mpi: more than 2^31 values between two ranks in one exchange");
  return static_cast<int>(values);
}

// Rows [first, last) that two row ranges share (empty when last <= first).
struct Overlap {
  Index first, last;
  Index rows() const { return std::max<Index>(last - first, 0); }
};
Overlap overlap(Index start_a, Index count_a, Index start_b, Index count_b, Index limit) {
  return {std::max(start_a, start_b), std::min({start_a + count_a, start_b + count_b, limit})};
}

}  // namespace

DistributedHalfSpace::DistributedHalfSpace(const Grid& grid, Real modulus, MPI_Comm comm, int threads)
    : grid_(grid), slab_(slab_of(grid, comm)), comm_(comm) {
  validate(grid, "distributed half-space grid");
  if (!(std::isfinite(modulus) && modulus > 0))
    throw Error("half-space: the modulus E* must be finite and > 0 Pa, got " + std::to_string(modulus));
  const bool padded = !grid.periodic;
  const Index lx = padded ? 2 * grid.nx : grid.nx, ly = padded ? 2 * grid.ny : grid.ny;
  fft_ = std::make_unique<DistributedRealFft2d>(lx, ly, comm, threads);
  const Index columns = fft_->spectrum_count(), first_column = fft_->spectrum_start();
  multiplier_.assign(static_cast<std::size_t>(columns * ly), 0.0);

  if (!padded) {
    // 2/(E* |q|) with the pair's 1/(nx ny) folded in, 0 at q = 0 (bem/half_space.cpp).
    const HalfLattice lattice(grid);
    const Real scale = 2 / (modulus * static_cast<Real>(grid.points()));
    for (Index c = 0; c < columns; ++c)
      for (Index row = 0; row < ly; ++row) {
        const Real qx = lattice.qx(first_column + c), qy = lattice.qy(row);
        const Real q = std::sqrt(qy * qy + qx * qx);
        multiplier_[static_cast<std::size_t>(c * ly + row)] = q > 0 ? scale / q : 0.0;
      }
  } else {
    // Love's kernel on the doubled lattice, offsets wrapped (bem/half_space.cpp), transformed by the same
    // distributed transform; it is even, so its transform is real. The pair's 1/(4 nx ny) is folded in.
    const Index nx = grid.nx, ny = grid.ny;
    const Real dx = grid.dx(), dy = grid.dy();
    const Slab& padded_slab = fft_->slab();
    for (Index r = 0; r < padded_slab.count; ++r) {
      const Index iy = padded_slab.start + r;
      double* row = fft_->real_row(r);
      for (Index ix = 0; ix < lx; ++ix) {
        const Real x = static_cast<Real>(ix < nx ? ix : ix - 2 * nx) * dx;
        const Real y = static_cast<Real>(iy < ny ? iy : iy - 2 * ny) * dy;
        row[ix] = love_displacement(x, y, dx / 2, dy / 2) / modulus;
      }
    }
    fft_->forward();
    const Complex* spectrum = fft_->spectrum();
    for (Index i = 0; i < columns * ly; ++i)
      multiplier_[static_cast<std::size_t>(i)] = spectrum[i].real() / static_cast<Real>(4 * nx * ny);

    // The exchange plan: this rank's grid rows to the padded slabs that hold them, and back.
    const auto grid_slabs = all_slabs(grid.nx, grid.ny, comm);
    const auto padded_slabs = all_slabs(lx, ly, comm);
    const int me = rank_of(comm);
    Index send_offset = 0, receive_offset = 0;
    for (std::size_t r = 0; r < grid_slabs.size(); ++r) {
      const Index sent =
          overlap(slab_.start, slab_.count, padded_slabs[r].start, padded_slabs[r].count, ny).rows();
      const Index received = overlap(grid_slabs[r].start, grid_slabs[r].count, padded_slabs[me].start,
                                     padded_slabs[me].count, ny)
                                 .rows();
      send_counts_.push_back(checked_int(sent * nx));
      send_offsets_.push_back(checked_int(send_offset));
      receive_counts_.push_back(checked_int(received * nx));
      receive_offsets_.push_back(checked_int(receive_offset));
      send_offset += sent * nx;
      receive_offset += received * nx;
    }
    receive_buffer_.resize(static_cast<std::size_t>(std::max<Index>(receive_offset, 1)));
  }

  // G(0) = sum of the multiplier over the full lattice: each stored column kx stands for +kx and -kx,
  // except kx = 0 and the Nyquist column (even lx).
  double sum = 0;
  for (Index c = 0; c < columns; ++c) {
    const Index kx = first_column + c;
    const double weight = (kx == 0 || (lx % 2 == 0 && kx == lx / 2)) ? 1.0 : 2.0;
    for (Index row = 0; row < ly; ++row)
      sum += weight * multiplier_[static_cast<std::size_t>(c * ly + row)];
  }
  self_response_ = sum_over_ranks(sum, comm);
}

DistributedHalfSpace::~DistributedHalfSpace() = default;

void DistributedHalfSpace::to_transform(const Real* pressure) {
  if (grid_.periodic) {
    fft_->load(pressure);
    return;
  }
  // Zero padding: the transform's slab is cleared (the previous inverse wrote all of it), then the grid
  // rows it owns arrive from their ranks, in rank order, hence in row order.
  const Slab& padded = fft_->slab();
  for (Index r = 0; r < padded.count; ++r)
    std::fill_n(fft_->real_row(r), padded.nx, 0.0);
  MPI_Alltoallv(pressure, send_counts_.data(), send_offsets_.data(), MPI_DOUBLE, receive_buffer_.data(),
                receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE, comm_);
  const Index rows = overlap(0, grid_.ny, padded.start, padded.count, grid_.ny).rows();
  for (Index r = 0; r < rows; ++r)
    std::copy_n(receive_buffer_.data() + r * grid_.nx, grid_.nx, fft_->real_row(r));
}

void DistributedHalfSpace::from_transform(Real* displacement) {
  if (grid_.periodic) {
    fft_->store(displacement);
    return;
  }
  const Slab& padded = fft_->slab();
  const Index rows = overlap(0, grid_.ny, padded.start, padded.count, grid_.ny).rows();
  for (Index r = 0; r < rows; ++r)
    std::copy_n(fft_->real_row(r), grid_.nx, receive_buffer_.data() + r * grid_.nx);
  // The reverse of to_transform's exchange: what was received goes back where it came from.
  MPI_Alltoallv(receive_buffer_.data(), receive_counts_.data(), receive_offsets_.data(), MPI_DOUBLE,
                displacement, send_counts_.data(), send_offsets_.data(), MPI_DOUBLE, comm_);
}

void DistributedHalfSpace::apply(const Real* pressure, Real* displacement) {
  to_transform(pressure);
  fft_->forward();
  Complex* spectrum = fft_->spectrum();
  const std::size_t values = multiplier_.size();
  for (std::size_t i = 0; i < values; ++i)
    spectrum[i] *= multiplier_[i];
  fft_->backward();
  from_transform(displacement);
}

}  // namespace contactbench::mpi
