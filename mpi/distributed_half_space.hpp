// The elastic half-space operator u = G p (bem/half_space.hpp, docs/theory.md section 6) on a grid split in
// slabs (docs/mpi.md): each rank passes its slab of the pressure and gets its slab of the displacement.
// Periodic: the multiplier 2/(E* |q|) on the grid's lattice. Non-periodic: the pressure zero-padded to
// 2 nx x 2 ny and convolved with Love's kernel (mpi/distributed_convolution.hpp).
// Also the solver's Fourier preconditioner (bem/fourier_preconditioner.hpp), the same kind of convolution.
#pragma once

#include <memory>

#include <mpi.h>

#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"
#include "contactbench/mpi/distributed_convolution.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

class DistributedHalfSpace {
 public:
  // Collective. grid.periodic chooses the operator, as bem's make_half_space does.
  DistributedHalfSpace(const Grid& grid, Real modulus, MPI_Comm comm, int threads = 1);

  const Grid& grid() const { return grid_; }
  const Slab& slab() const { return convolution_->slab(); }  // the pressure's and displacement's layout
  // G(0): the displacement at a pixel of a unit pressure on that pixel alone [m/Pa] (as bem's self_response).
  double self_response() const { return convolution_->self_response(); }

  std::size_t bytes() const { return convolution_->bytes(); }
  // The convolution, for another to share its transform (make_distributed_unit_preconditioner).
  const DistributedConvolution& convolution() const { return *convolution_; }

  // displacement = G pressure on this rank's slab (slab().count x nx, row-major); the arrays may be the same.
  // Collective.
  void apply(const Real* pressure, Real* displacement) { convolution_->apply(pressure, displacement); }
  // The same through the convolution's row callbacks and spectral product (DistributedConvolution::apply).
  void apply(const DistributedConvolution::RowProducer& produce,
             const DistributedConvolution::RowConsumer& consume,
             const std::function<void(double)>& multiplied = {}) {
    convolution_->apply(produce, consume, multiplied);
  }

 private:
  Grid grid_;
  std::unique_ptr<DistributedConvolution> convolution_;
};

// The filter (E*/2)|q| of bem/fourier_preconditioner.hpp: circular on the grid's lattice when it is periodic,
// else on the doubled, zero-padded lattice. Collective.
std::unique_ptr<DistributedConvolution> make_distributed_preconditioner(const Grid& grid, Real modulus,
                                                                        MPI_Comm comm, int threads = 1);

// The same filter scaled to a largest value of 1, as bem's make_unit_fourier_preconditioner (the same
// multiplier values): the active-set method's filter (mpi/distributed_active_set.hpp). `share`: a convolution
// of the same lattice (the operator's, when the grid is periodic or both are padded) whose transform it uses.
// `single_precision`: on the slab engine, the transform in float (DistributedConvolution), as the solver's
// filter runs (mpi/distributed_active_set.cpp). Collective.
std::unique_ptr<DistributedConvolution> make_distributed_unit_preconditioner(
    const Grid& grid, MPI_Comm comm, int threads = 1, const DistributedConvolution* share = nullptr,
    bool single_precision = false);

}  // namespace contactbench::mpi
