// The preconditioner of the constrained conjugate gradient (bem/bem_solver.hpp, solver
// "preconditioned_cg"; docs/solvers.md): the gap residual r [m] filtered in Fourier space by the inverse of
// the periodic half-space's symbol, z(q) = (E*/2) |q| r(q) [Pa]. The operator G (u(q) = 2 p(q)/(E* |q|),
// docs/theory.md section 6) has eigenvalues spread over the whole |q| range of the lattice, so its condition
// number grows like the number of points and plain CG needs ~sqrt(N) iterations; filtered by |q|, the
// spectrum of the contact-restricted problem is bunched far more tightly (not entirely: restricting to the
// contact set does not commute with the filter, and the count still grows with the grid, measured in
// results/bench/bem_solvers.md). The idea of mass-weighted GFMD (Zhou, Moseler & Mueser, Phys. Rev. B 99,
// 144103, 2019).
//
// For the non-periodic (zero-padded) operator the filter is applied the same way, to the residual zero-padded
// to 2 nx x 2 ny, with |q| of that doubled lattice: the residual then has no periodic images, as the
// free-space kernel has none. Measured on surface A refined (bench/bench_bem_solvers.cpp, 256^2 and 512^2,
// 10 % and 30 % contact): 20 % to 50 % fewer iterations than the same filter circular on the nx x ny grid,
// for 3/4 of a padded FFT pair instead of one unpadded pair. The q = 0 mode is set to 0: the solver takes the
// mean out of z on the contact set afterwards, which removes whatever that mode held.
#pragma once

#include <memory>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/grid.hpp"

namespace contactbench {

// The lattice the filter's wavevectors live on: the grid itself when it is periodic, else its zero-padded
// double (2 nx x 2 ny over 2 lx x 2 ly). The distributed filter (mpi/distributed_half_space.cpp) uses it too.
Grid filter_lattice(const Grid& grid);

// The filter (E*/2)|q|: circular on the grid's own lattice when the grid is periodic, else on the doubled,
// zero-padded lattice; in double or single precision; modulus is E* [Pa].
template <class T>
std::unique_ptr<Convolution<T>> make_fourier_preconditioner(const Grid& grid, Real modulus, int threads = 1);

// The same filter scaled to a largest value of 1 (|q| / max |q|, and the transform pair normalised) whatever
// the units of the grid and the modulus: for a preconditioned CG (invariant to a constant factor of its
// preconditioner) that runs the filter in single precision, where E* of 1e90 Pa or a pixel of 1e-90 m would
// leave float's range.
// `rigor`: how its plans are made (Convolution).
template <class T>
std::unique_ptr<Convolution<T>> make_unit_fourier_preconditioner(const Grid& grid, int threads = 1,
                                                                 FftRigor rigor = FftRigor::by_work);

}  // namespace contactbench
