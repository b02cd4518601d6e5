// The FFT engine under the half-space operators: out = IDFT(M . DFT(in)) for a real, even multiplier M,
// circular on the grid (periodic) or linear by zero padding to 2 nx x 2 ny (non-periodic), in double or
// single precision (FFTW's fftw_* or fftwf_* interface).
//
// Why not RealFft2d: an iteration of the Polonsky-Keer solver is two such convolutions plus element-wise
// work, and on two cores that work costs as much as the transforms when it runs as separate passes over
// full arrays (copies into and out of the FFT's buffers, masks, sums). Here one apply() is one OpenMP
// region of three stages, and the caller's element-wise work rides along inside it, on data in cache:
//   1. rows: for each chunk of rows, `produce` writes the input rows into a small per-thread buffer (the
//      zero padding already in place), and a real-to-complex transform of those rows follows;
//   2. columns: for each block of columns, copy into a per-thread buffer (zero-padded), transform, multiply
//      by M, transform back, copy back; the padded half of the result is never stored. One plan serves
//      every block (a last block of fewer columns is padded with zero columns) and both directions (back
//      is forward between two conjugations, folded into the multiplication and the copy back); the row plans
//      are always estimated, so that a first run measures one plan, not six (docs/solvers.md, Planning);
//   3. rows: complex-to-real of each chunk of rows into a per-thread buffer, which `consume` reads.
// So the input is read from and the output written to the caller's own arrays: there are no full-size
// copies, and the non-periodic transform skips the all-zero rows of the padding (3/4 of the work of a
// full 2 nx x 2 ny pair). Each stage splits its chunks statically over the team, so for a fixed thread
// count the arithmetic (and any reduction the caller keeps per thread) is the same from run to run.
//
// Plans are single-threaded FFTW plans of one chunk, executed by the team's threads (FFTW's new-array
// execute); on grids below kMinPointsForThreads points (of the transform) the team is one thread. One
// Convolution serves one caller at a time (its spectrum and buffers are shared by the stages).
#pragma once

#include <cstdint>
#include <memory>
#include <type_traits>

#include "contactbench/core/fft.hpp"
#include "contactbench/core/types.hpp"

namespace contactbench {

// A non-owning reference to a callable, for the per-chunk callbacks (one indirect call per chunk of rows).
template <class Signature>
class FunctionRef;
template <class R, class... Args>
class FunctionRef<R(Args...)> {
 public:
  FunctionRef() = default;
  template <class F>
  requires(!std::is_same_v<std::remove_cv_t<F>, FunctionRef>)
      FunctionRef(F& f)  // NOLINT(google-explicit-constructor): a reference, like std::function_ref
      : object_(&f), call_([](void* o, Args... a) -> R { return (*static_cast<F*>(o))(a...); }) {}
  R operator()(Args... a) const { return call_(object_, a...); }
  explicit operator bool() const { return call_ != nullptr; }

 private:
  void* object_ = nullptr;
  R (*call_)(void*, Args...) = nullptr;
};

template <class T>
class Convolution {
 public:
  // produce(first_row, rows, buffer, ld, thread): write rows [first_row, first_row + rows) of the input,
  // nx values each, row r at buffer + r * ld (the padding beyond nx is the engine's and stays zero).
  using Producer = FunctionRef<void(Index, Index, T*, Index, int)>;
  // consume(first_row, rows, buffer, ld, thread): rows of the output, nx values each, row r at buffer + r*ld.
  using Consumer = FunctionRef<void(Index, Index, const T*, Index, int)>;
  // Run by one thread once every row is produced and before any is consumed (e.g. to combine the
  // producers' sums into what the consumers need).
  using Hook = FunctionRef<void()>;
  // Run by one thread once the spectrum is multiplied and before any row is transformed back, with the
  // product in . out (e.g. a step length that the consumers then apply).
  using ProductHook = FunctionRef<void(double)>;

  // nx x ny grid; `padded`: linear convolution (zero padding to 2 nx x 2 ny), else circular. `rigor`: how
  // the plans are made (by default chosen by the run's work, core/fft.hpp choose_fft_rigor, after measured
  // plans the wisdom holds already; lattices below kMinPointsForThreads points are always estimated).
  Convolution(Index nx, Index ny, bool padded, int threads, FftRigor rigor = FftRigor::by_work);
  ~Convolution();
  Convolution(const Convolution&) = delete;
  Convolution& operator=(const Convolution&) = delete;

  Index nx() const { return nx_; }
  Index ny() const { return ny_; }
  bool padded() const { return padded_; }
  // The transform's lattice: lx() x ly() (= nx x ny, or 2 nx x 2 ny padded); the multiplier is given on its
  // half spectrum, ly() rows by lx()/2 + 1 columns, and must be even in ky (M(ky) = M(ly - ky)): only rows
  // 0 .. ly()/2 are kept.
  Index lx() const { return lx_; }
  Index ly() const { return ly_; }
  // Threads of the team apply() runs (1 below kMinPointsForThreads points of the transform's lattice); the
  // `thread` argument of the callbacks is below this.
  int threads() const { return threads_; }
  // How the plans were made: measure (by measuring, or from the wisdom of an earlier measurement) or
  // estimate.
  FftRigor planned_rigor() const { return planned_rigor_; }

  // The multiplier, the normalisation 1/(lx ly) of the transform pair folded in. Double whatever T is.
  void set_multiplier(const Eigen::Array<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>& m);
  // G(0): the output at a point of a unit input at that point alone, sum over the lattice of M.
  double self_response() const { return self_response_; }

  // out = conv(in) through the callbacks. With `product`, returns in . out = sum_k M_k |in_k|^2 (over the
  // full lattice), computed in the spectral domain while the transform passes (else 0). With an empty
  // `consume` the inverse transform is skipped (half the cost): only the product is computed. A non-empty
  // `multiplied` is given that product before any row is consumed (it implies `product`).
  double apply(Producer produce, Consumer consume, Hook between = {}, bool product = false,
               ProductHook multiplied = {});

  // Plain arrays: out (ny x nx, row-major) = conv(in); in and out may be the same array.
  void apply(const T* in, T* out);

 private:
  struct Impl;
  Index nx_, ny_;
  bool padded_;
  Index lx_, ly_;
  int threads_;
  FftRigor planned_rigor_ = FftRigor::estimate;
  double self_response_ = 0;
  std::unique_ptr<Impl> impl_;
};

extern template class Convolution<double>;
extern template class Convolution<float>;

}  // namespace contactbench
