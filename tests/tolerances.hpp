// Named tolerances for numerical tests, each with the reason for its size (docs/architecture.md conventions).
#pragma once

namespace contactbench::tolerance {

// Round-off of an O(N log N) FFT pair in double on grids up to 1024^2: a few 1e-16 times log2(N) per step.
inline constexpr double fft_round_off = 1e-12;
// Lattice moments against the paper's Table 2, which prints three significant digits (issue: 1 %).
inline constexpr double table2 = 1e-2;
// Moments of a Fourier-interpolated surface: the same coefficients, only summed again (issue: 1e-10).
inline constexpr double refined_moments = 1e-10;
// Heights of a Fourier-interpolated surface at the original nodes: two FFTs of round-off (issue: 1e-12).
inline constexpr double refined_nodes = 1e-12;
// Sq of the measured files against SurfaceTopography's asserted values (issue: 1e-9); both are
// double-precision sums of the same decimal data, so agreement is limited only by summation order.
inline constexpr double measured_sq = 1e-9;
// Requested m2x/m2y of an anisotropic surface: the lattice cuts the spectrum's ellipse (issue: 2 %).
inline constexpr double anisotropy_ratio = 2e-2;

// Two Polonsky-Keer solves of one problem (or of an exactly equivalent one: transposed, scaled, warm- or
// cold-started), each stopped at a relative pressure change of 1e-12: their pressures differ by a modest
// multiple of that tolerance, measured 1e-14..1e-11 of the peak pressure; 1e-9 leaves a factor 100.
inline constexpr double solver_consistency = 1e-9;

// A theory's solved loads (GW, BGT) against the requested ones (issue: 1e-10): its root finder stops at 1e-13
// in ln P.
inline constexpr double solved_load = 1e-10;

}  // namespace contactbench::tolerance
