// The elastic half-space as a boundary-element operator: the normal surface displacement u = G p of a
// pressure field p sampled on a grid (docs/theory.md section 6). One application costs one FFT pair (for the
// non-periodic operator, 3/4 of a pair of the padded size: the all-zero rows of the padding are skipped;
// bem/convolution.hpp).
#pragma once

#include <memory>

#include "contactbench/bem/convolution.hpp"
#include "contactbench/core/grid.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

class HalfSpace {
 public:
  virtual ~HalfSpace() = default;

  // displacement [m] of the pressure [Pa] on the operator's grid (ny x nx); displacement is resized.
  virtual void apply(const HeightMap& pressure, HeightMap& displacement) = 0;
  // The same on plain row-major ny x nx arrays, without copies: the transform reads the pressure from and
  // writes the displacement into these arrays directly (they may be the same array).
  virtual void apply(const Real* pressure, Real* displacement) = 0;

  const Grid& grid() const { return grid_; }
  Real modulus() const { return modulus_; }  // E* [Pa] (docs/theory.md section 0)

 protected:
  HalfSpace(const Grid& grid, Real modulus);

 private:
  Grid grid_;
  Real modulus_;
};

// Periodic half-space (Westergaard/Fourier): u(q) = 2 p(q)/(E* |q|) for q != 0. The q = 0 mode (the mean
// displacement) is set to 0: the mean pressure and the rigid-body approach are the solver's business.
std::unique_ptr<HalfSpace> make_periodic_half_space(const Grid& grid, Real modulus, int threads = 1);

// Non-periodic half-space: the pressure zero-padded to 2 nx x 2 ny and convolved with the exact displacement
// of a uniformly loaded pixel (Love's kernel), whose transform is computed once per operator. Exact for a
// pressure that is piecewise constant on the pixels.
std::unique_ptr<HalfSpace> make_nonperiodic_half_space(const Grid& grid, Real modulus, int threads = 1);

// The operator a grid calls for: periodic or not, as grid.periodic says.
std::unique_ptr<HalfSpace> make_half_space(const Grid& grid, Real modulus, int threads = 1);

// The engine of the operator a grid calls for, in double or single precision, for callers that fuse their
// own element-wise work into the transforms (the Polonsky-Keer solver). Its self_response() is the
// displacement of a unit pressure on one pixel at that pixel [m/Pa]. `rigor`: how its plans are made
// (bem/convolution.hpp).
template <class T>
std::unique_ptr<Convolution<T>> make_half_space_convolution(const Grid& grid, Real modulus, int threads = 1,
                                                            FftRigor rigor = FftRigor::by_work);

}  // namespace contactbench
