// The preconditioner of the constrained conjugate gradient (bem/polonsky_keer.hpp, solver
// "preconditioned_cg"; docs/solvers.md): the gap residual r [m] filtered in Fourier space by the inverse of
// the periodic half-space's symbol, z(q) = (E*/2) |q| r(q) [Pa]. The operator G (u(q) = 2 p(q)/(E* |q|),
// docs/theory.md section 6) has eigenvalues spread over the whole |q| range of the lattice, so its condition
// number grows like the number of points and plain CG needs ~sqrt(N) iterations; filtered by |q|, the
// spectrum of the contact-restricted problem is bunched near 1, whatever the grid (the idea of mass-weighted
// GFMD, Zhou, Moseler & Mueser, Phys. Rev. B 99, 144103, 2019).
//
// The filter is circular on the nx x ny grid for the non-periodic (padded) operator too: a preconditioner
// needs only to approximate the inverse, and the free-space kernel has the same symbol 2/(E*|q|) away from
// the longest wavelengths; it costs one unpadded FFT pair. The q = 0 mode is set to 0: the solver takes the
// mean out of z on the contact set afterwards, which removes whatever that mode held.
#pragma once

#include <memory>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/grid.hpp"

namespace contactbench {

// The filter (E*/2)|q| on the grid's own (unpadded, circular) lattice, in double or single precision;
// modulus is E* [Pa].
template <class T>
std::unique_ptr<Convolution<T>> make_fourier_preconditioner(const Grid& grid, Real modulus, int threads = 1);

}  // namespace contactbench
