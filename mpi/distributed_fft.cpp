#include "contactbench/mpi/distributed_fft.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include <fftw3-mpi.h>

#include "contactbench/core/error.hpp"
#include "contactbench/core/fft.hpp"
#include "contactbench/mpi/environment.hpp"

namespace contactbench::mpi {

SpectrumColumns2d spectrum_columns(Index nx, Index ny, MPI_Comm comm) {
  require_fftw_mpi();
  ptrdiff_t rows = 0, row_start = 0, columns = 0, column_start = 0;
  fftw_mpi_local_size_2d_transposed(ny, nx / 2 + 1, comm, &rows, &row_start, &columns, &column_start);
  return {column_start, columns};
}

DistributedRealFft2d::DistributedRealFft2d(Index nx, Index ny, MPI_Comm comm, int threads)
    : slab_(slab_of(nx, ny, comm)), comm_(comm) {
  require_fftw_mpi();
  ptrdiff_t rows = 0, row_start = 0, columns = 0, column_start = 0;
  const ptrdiff_t complex_values =
      fftw_mpi_local_size_2d_transposed(ny, nx / 2 + 1, comm, &rows, &row_start, &columns, &column_start);
  if (rows != slab_.count || (rows > 0 && row_start != slab_.start))
    throw Error("mpi: FFTW-MPI's split of the rows differs from the slab layout (docs/mpi.md)");
  spectrum_start_ = column_start;
  spectrum_count_ = columns;
  bytes_ = sizeof(fftw_complex) * static_cast<std::size_t>(std::max<ptrdiff_t>(complex_values, 1));
  data_ = fftw_alloc_complex(static_cast<std::size_t>(std::max<ptrdiff_t>(complex_values, 1)));
  if (!data_)
    throw Error("mpi: out of memory for a slab of " + std::to_string(nx) + " x " + std::to_string(ny));
  std::memset(static_cast<void*>(data_), 0, sizeof(fftw_complex) * static_cast<std::size_t>(complex_values));
  {
    // FFTW's planner is process-wide and not thread-safe (core/fft.hpp); planning is collective over comm.
    auto lock = lock_fftw_planner();
    fftw_plan_with_nthreads(std::max(threads, 1));
    auto* real = reinterpret_cast<double*>(data_);
    forward_plan_ =
        fftw_mpi_plan_dft_r2c_2d(ny, nx, real, data_, comm, FFTW_ESTIMATE | FFTW_MPI_TRANSPOSED_OUT);
    backward_plan_ =
        fftw_mpi_plan_dft_c2r_2d(ny, nx, data_, real, comm, FFTW_ESTIMATE | FFTW_MPI_TRANSPOSED_IN);
    fftw_plan_with_nthreads(1);
  }
  if (!forward_plan_ || !backward_plan_)
    throw Error("mpi: FFTW-MPI could not plan the distributed transform");
}

DistributedRealFft2d::~DistributedRealFft2d() {
  auto lock = lock_fftw_planner();
  if (forward_plan_) fftw_destroy_plan(forward_plan_);
  if (backward_plan_) fftw_destroy_plan(backward_plan_);
  fftw_free(data_);
}

void DistributedRealFft2d::forward() {
  fftw_execute(forward_plan_);
}

void DistributedRealFft2d::backward() {
  fftw_execute(backward_plan_);
}

void DistributedRealFft2d::load(const Real* slab_values) {
  for (Index r = 0; r < slab_.count; ++r)
    std::copy_n(slab_values + r * slab_.nx, slab_.nx, real_row(r));
}

void DistributedRealFft2d::store(Real* slab_values) {
  for (Index r = 0; r < slab_.count; ++r)
    std::copy_n(real_row(r), slab_.nx, slab_values + r * slab_.nx);
}

}  // namespace contactbench::mpi
