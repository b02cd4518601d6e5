// Random self-affine surfaces: the paper's generator (docs/theory.md section 2) and Fourier refinement.
#pragma once

#include <cstdint>
#include <optional>

#include "contactbench/core/spectrum.hpp"
#include "contactbench/core/surface.hpp"

namespace contactbench {

// PSD with roll-off and a radial cut (docs/theory.md section 2):
//   C = C0 for |q| < qr,  C0 (|q|/qr)^(-2(1+H)) for qr <= |q| <= qs,  0 above qs,
// with C0 fixed by sum_k C_k dqx dqy = sigma^2 on the lattice, and C = 0 at k = 0 and on the Nyquist
// row and column. Anisotropy: |q| -> sqrt((qx/gx)^2 + (qy/gy)^2), with gx/gy = sqrt(anisotropy) and
// max(gx, gy) = 1, which makes m2x/m2y = anisotropy (exactly in the continuum; the lattice adds a little)
// and keeps the cut-off ellipse inside the circle of radius qs, hence inside the lattice.
struct SelfAffinePsd {
  Real sigma = 0;          // rms height [m]
  Real hurst = 0;          // Hurst exponent H, in (0, 1]
  Real qr = 0;             // roll-off wavevector [1/m]
  std::optional<Real> qs;  // cut-off wavevector [1/m]; default: the grid's Nyquist wavevector
  Real anisotropy = 1;     // requested m2x/m2y

  // qs as it applies on `grid`.
  Real cutoff(const Grid& grid) const { return qs.value_or(grid.nyquist()); }
};

// Throws Error naming the parameter and its accepted range unless psd is usable on grid.
void validate(const SelfAffinePsd& psd, const Grid& grid);

// The coefficients of a realisation one mode at a time, for code that computes only some of them (the
// distributed generator, mpi/, where each rank computes the modes it owns): generate_coefficients is this
// class, mode by mode over the half lattice, so both give the same bits.
class SelfAffineModes {
 public:
  // Validates psd on grid. The normalisation is the lattice sum of the PSD's shape over the whole half
  // lattice, summed as one array (4 B per grid point, freed on return) so that its rounding never depends on
  // who asks.
  SelfAffineModes(const Grid& grid, const SelfAffinePsd& psd);

  // hhat at (row, col) of the half lattice (FFTW order, spectrum.hpp's HalfLattice) for `seed`.
  Complex coefficient(Index row, Index col, std::uint64_t seed) const;

 private:
  Real shape(Index row, Index col) const;  // C / C0 at that mode
  HalfLattice lattice_;
  Real qr_, qs_, gx_, gy_, exponent_;
  Real scale_ = 0;  // sigma / sqrt(lattice sum of the shape)
};

// Fourier-series coefficients hhat_k of a random realisation: deterministic modulus sqrt(C_k dqx dqy),
// random phase with phi_{-k} = -phi_k. Each phase is a hash of (seed, kx, ky), so the realisation does not
// depend on the order of evaluation or the thread count.
SpectrumMap generate_coefficients(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed);

// The surface h(x) = sum_k hhat_k exp(i q_k.x) on `grid` (periodic). Bit-identical for any thread count.
Surface generate_surface(const Grid& grid, const SelfAffinePsd& psd, std::uint64_t seed, int threads = 1);

// Fourier interpolation: the surface whose coefficients on `grid` are `hhat` (as generate_coefficients
// returns them), sampled on nx x ny >= grid's points over the same lateral size. A Nyquist coefficient is
// split evenly between +k and -k, so the heights at the original nodes are kept. Bit-identical for any
// thread count.
Surface synthesize(const Grid& grid, const SpectrumMap& hhat, Index nx, Index ny, int threads = 1);

// The same periodic surface resampled on nx x ny >= its own points by Fourier interpolation: its moments are
// unchanged and its heights at the original nodes too (to round-off). Refuses a non-periodic surface.
Surface refine(const Surface& surface, Index nx, Index ny, int threads = 1);

// The paper's inputs (docs/theory.md section 2, Table 1): L = 200 um, 256 x 256, periodic.
namespace paper {
Grid grid();
// Surface A: sigma = 0.5 um, H = 0.5, qr = 3.14e4 1/m, qs = 4.02e6 1/m (the Nyquist wavevector).
SelfAffinePsd surface_a();
// Surface B with qs at Nyquist, which reproduces Table 2; Table 1 prints qs = 3.00e6 instead.
SelfAffinePsd surface_b();
// Surface B with the qs = 3.00e6 1/m printed in Table 1 (gives m2 = 0.0337, m4 = 0.0492 um^-2, not Table 2).
SelfAffinePsd surface_b_printed_qs();
}  // namespace paper

}  // namespace contactbench
