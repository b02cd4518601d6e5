// The elastic half-space operator u = G p (bem/half_space.hpp, docs/theory.md section 6) on a grid split in
// slabs (docs/mpi.md): each rank passes its slab of the pressure and gets its slab of the displacement; the
// transform is FFTW-MPI's (mpi/distributed_fft.hpp). Periodic: the multiplier 2/(E* |q|) on the grid's
// lattice. Non-periodic: the pressure zero-padded to 2 nx x 2 ny and convolved with Love's kernel, the
// padded field split in slabs of its own (rows of 2 ny) and the physical rows moved to and from it by one
// all-to-all each way.
#pragma once

#include <memory>
#include <vector>

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/mpi/distributed_fft.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

class DistributedHalfSpace {
 public:
  // Collective. grid.periodic chooses the operator, as bem's make_half_space does.
  DistributedHalfSpace(const Grid& grid, Real modulus, MPI_Comm comm, int threads = 1);
  ~DistributedHalfSpace();

  const Grid& grid() const { return grid_; }
  const Slab& slab() const { return slab_; }  // of the grid (the pressure's and displacement's layout)
  MPI_Comm comm() const { return comm_; }
  // G(0): the displacement at a pixel of a unit pressure on that pixel alone [m/Pa] (as bem's self_response).
  double self_response() const { return self_response_; }

  // displacement = G pressure on this rank's slab (slab().count x nx, row-major); the arrays may be the same.
  // Collective.
  void apply(const Real* pressure, Real* displacement);

 private:
  void to_transform(const Real* pressure);
  void from_transform(Real* displacement);

  Grid grid_;
  Slab slab_;
  MPI_Comm comm_;
  std::unique_ptr<DistributedRealFft2d> fft_;
  std::vector<double> multiplier_;  // on the transform's spectral columns, normalisation folded in
  double self_response_ = 0;
  // Non-periodic only: how the grid's rows travel to the padded transform's slabs (counts, offsets in
  // values).
  std::vector<int> send_counts_, send_offsets_, receive_counts_, receive_offsets_;
  std::vector<double> receive_buffer_;  // the padded slab's grid rows, in row order
};

}  // namespace contactbench::mpi
