// FFT engine over FFTW: real-to-complex 2D plans made once per shape and reused.
//
// Conventions (docs/theory.md section 1): forward is the unnormalised sum_x h(x) exp(-i q_k.x); backward is
// the unnormalised sum_k c_k exp(+i q_k.x) over the full lattice, given its Hermitian half (types.hpp).
// Divide the forward result by nx * ny to get the Fourier-series coefficients hhat_k.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>

#include <fftw3.h>

#include "contactbench/core/types.hpp"

namespace contactbench {

// How hard FFTW searches for a fast plan: `estimate` plans instantly, `measure` times candidates
// (seconds for large grids) and pays off only for the many transforms of a solver; `by_work` lets the
// planner choose by the run's work (choose_fft_rigor below; docs/solvers.md, Planning).
enum class FftRigor { estimate, measure, by_work };

// What a run tells the planner about its work, for FftRigor::by_work: whether FFTW's wisdom is kept in a file
// (a measured plan is then paid once per machine, not once per run) and how many convolutions the run
// expects to apply on its finest grid. Process-wide; the commands set it before their solves.
struct FftWork {
  bool wisdom_kept = false;
  double expected_applications = 0;
};
void set_fft_work(const FftWork& work);
FftWork fft_work();

// Transform lattices below this many points are always estimated: a measured plan there never pays back
// its planning within a run (docs/solvers.md, Planning: 256^2 needs 860-3,300 applications).
inline constexpr Index kMinPointsForMeasuredPlans = Index{512} * 512;
// Applications of one convolution that pay back measuring its plans at 512^2 and above (docs/solvers.md,
// Planning: 440-2,000 measured, the largest taken so that a measured plan made for its own run surely pays).
inline constexpr double kPayBackApplications = 2000;

// FftRigor::by_work resolved for a lattice of `points` points, when no wisdom holds its plans already (the
// caller tries FFTW_WISDOM_ONLY first): measure when the lattice is large enough and the wisdom is kept or
// the run's expected applications exceed the pay-back count; estimate otherwise. `estimate` and `measure`
// are returned as given.
FftRigor choose_fft_rigor(FftRigor asked, Index points);

// A 2D real <-> half-complex transform of one shape, with its own aligned buffers.
// Transforms run on `threads` threads. One RealFft2d serves one caller at a time; creating and destroying
// plans is thread-safe (FFTW's planner is guarded by a process-wide lock).
class RealFft2d {
 public:
  RealFft2d(Index nx, Index ny, int threads = 1, FftRigor rigor = FftRigor::estimate);
  ~RealFft2d();
  RealFft2d(const RealFft2d&) = delete;
  RealFft2d& operator=(const RealFft2d&) = delete;

  Index nx() const { return nx_; }
  Index ny() const { return ny_; }
  Index nx_half() const { return nx_ / 2 + 1; }
  int threads() const { return threads_; }

  // The plan's own buffers, for callers that transform in place without copies (ny x nx, ny x nx/2+1).
  Eigen::Map<HeightMap> real() { return {real_, ny_, nx_}; }
  Eigen::Map<SpectrumMap> spectrum() { return {reinterpret_cast<Complex*>(spectrum_), ny_, nx_half()}; }
  void forward();   // spectrum() <- forward(real())
  void backward();  // real() <- backward(spectrum()); spectrum() is destroyed (FFTW's multi-dim c2r)

  // Copying conveniences; `in` is left untouched.
  void forward(const HeightMap& in, SpectrumMap& out);
  void backward(const SpectrumMap& in, HeightMap& out);

 private:
  Index nx_, ny_;
  int threads_;
  double* real_ = nullptr;
  fftw_complex* spectrum_ = nullptr;
  fftw_plan forward_plan_ = nullptr;
  fftw_plan backward_plan_ = nullptr;
};

// A plan of this shape and thread count for the calling thread, made on first use and kept for reuse.
RealFft2d& cached_fft(Index nx, Index ny, int threads = 1);

// For code that makes its own FFTW plans (double fftw_* or single fftwf_*): FFTW's planners are not
// thread-safe, so every plan creation and destruction must hold this process-wide lock, the one RealFft2d
// holds. Taking it also initialises FFTW's thread support for both precisions (once), so that
// fftw_plan_with_nthreads / fftwf_plan_with_nthreads may be called under it.
std::unique_lock<std::mutex> lock_fftw_planner();

// Seconds this process has spent making FFTW plans (every FftwPlanningClock's span, summed), so that a run
// can report planning as its own cost: with FFTW_MEASURE and no wisdom it can exceed the solve.
double fftw_planning_seconds();

// Adds the time from its construction to its destruction to fftw_planning_seconds(). Made beside the planner
// lock around plan creation (not destruction, which is quick).
class FftwPlanningClock {
 public:
  FftwPlanningClock();
  ~FftwPlanningClock();
  FftwPlanningClock(const FftwPlanningClock&) = delete;
  FftwPlanningClock& operator=(const FftwPlanningClock&) = delete;

 private:
  std::chrono::steady_clock::time_point start_;
};

// The backward transform with a result that is bit-identical for any thread count: the 2D transform is done
// as 1D transforms over fixed chunks of lines, each chunk by the same single-threaded plan, so the
// arithmetic never depends on how chunks are shared among threads. Used where reproducibility is promised
// (surface generation).
class ReproducibleInverseFft2d {
 public:
  ReproducibleInverseFft2d(Index nx, Index ny);
  ~ReproducibleInverseFft2d();
  ReproducibleInverseFft2d(const ReproducibleInverseFft2d&) = delete;
  ReproducibleInverseFft2d& operator=(const ReproducibleInverseFft2d&) = delete;

  // out(x) = sum_k in_k exp(+i q_k.x); `in` is ny x (nx/2+1), `out` becomes ny x nx. Runs on `threads`.
  void backward(const SpectrumMap& in, HeightMap& out, int threads);

  // Lines per chunk. The distributed generator (mpi/) repeats these passes on the same chunks of columns
  // with the same plans, which is what makes its result bit-identical to this one.
  static constexpr Index kLinesPerChunk = 16;

 private:
  Index nx_, ny_;
  SpectrumMap work_;
  HeightMap result_;
  // Per chunk size (full chunk, remainder chunk): complex backward along y, then c2r along x.
  fftw_plan columns_full_ = nullptr, columns_rest_ = nullptr;
  fftw_plan rows_full_ = nullptr, rows_rest_ = nullptr;
};

}  // namespace contactbench
