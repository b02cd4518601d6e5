// Surface generation and spectral moments on slabs (docs/mpi.md).
#pragma once

#include <cstdint>

#include <mpi.h>

#include "contactbench/core/generation.hpp"
#include "contactbench/core/spectrum.hpp"
#include "contactbench/mpi/slab.hpp"

namespace contactbench::mpi {

// This rank's slab (slab_of(grid, comm), count x nx) of generate_surface(grid, psd, seed): bit-identical to
// the serial surface's rows whatever the number of ranks. Each rank computes the coefficients of its own
// chunks of kx columns (core's SelfAffineModes), which mpi/distributed_synthesis.hpp turns into row slabs
// with the serial generator's own transforms. The normalisation is summed over the whole half
// lattice on every rank (a temporary of 4 B per grid point), as the serial generator sums it, so that it
// rounds alike. Collective; throws the serial generator's errors on every rank.
HeightMap generate_surface_slab(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed,
                                MPI_Comm comm);

// The spectral moments of a surface given as slabs (count x nx on each rank), as core's spectral_moments
// (default window: none for a periodic grid, Hann otherwise); the transform is FFTW-MPI's and the lattice
// sums are MPI_Allreduce'd, so they equal the serial ones to round-off (not bit for bit). Collective.
SpectralMoments distributed_spectral_moments(const Grid& grid, const HeightMap& local_heights, MPI_Comm comm);

}  // namespace contactbench::mpi
