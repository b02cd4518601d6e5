#include "contactbench/core/fft.hpp"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <tuple>

#include <fftw3.h>
#include <omp.h>

#include "contactbench/core/error.hpp"

namespace contactbench {

namespace {

// FFTW's planner is not thread-safe: every plan creation and destruction goes through this lock.
std::mutex& planner_mutex() {
  static std::mutex mutex;
  return mutex;
}

void initialise_fftw_threads_once() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (fftw_init_threads() == 0) throw Error("FFTW: fftw_init_threads failed");
    if (fftwf_init_threads() == 0) throw Error("FFTW: fftwf_init_threads failed");
  });
}

unsigned planner_flags(FftRigor rigor) {
  return rigor == FftRigor::measure ? FFTW_MEASURE : FFTW_ESTIMATE;
}

std::mutex& work_mutex() {
  static std::mutex mutex;
  return mutex;
}
FftWork& work_setting() {
  static FftWork work;
  return work;
}

void check_shape(Index nx, Index ny) {
  if (nx < 1 || ny < 1)
    throw Error("FFT: shape must be at least 1 x 1, got " + std::to_string(nx) + " x " + std::to_string(ny));
}

void destroy(fftw_plan& plan) {
  if (plan) fftw_destroy_plan(plan);
  plan = nullptr;
}

}  // namespace

RealFft2d::RealFft2d(Index nx, Index ny, int threads, FftRigor rigor)
    : nx_(nx), ny_(ny), threads_(std::max(threads, 1)) {
  check_shape(nx, ny);
  initialise_fftw_threads_once();
  std::lock_guard lock(planner_mutex());
  const FftwPlanningClock clock;
  real_ = fftw_alloc_real(static_cast<size_t>(ny_ * nx_));
  spectrum_ = fftw_alloc_complex(static_cast<size_t>(ny_ * nx_half()));
  if (!real_ || !spectrum_)
    throw Error("FFT: out of memory for a " + std::to_string(nx) + " x " + std::to_string(ny) + " transform");
  fftw_plan_with_nthreads(threads_);
  // MEASURE overwrites the arrays while planning; they hold nothing yet.
  auto make_plans = [&](unsigned flags) {
    forward_plan_ =
        fftw_plan_dft_r2c_2d(static_cast<int>(ny_), static_cast<int>(nx_), real_, spectrum_, flags);
    backward_plan_ =
        fftw_plan_dft_c2r_2d(static_cast<int>(ny_), static_cast<int>(nx_), spectrum_, real_, flags);
  };
  // By the work: a measured plan the wisdom already holds costs nothing (FFTW_WISDOM_ONLY makes none
  // otherwise); else the rule decides.
  if (rigor == FftRigor::by_work && nx_ * ny_ >= kMinPointsForMeasuredPlans) {
    make_plans(FFTW_MEASURE | FFTW_WISDOM_ONLY);
    if (!forward_plan_ || !backward_plan_) {
      destroy(forward_plan_);
      destroy(backward_plan_);
    }
  }
  if (!forward_plan_) make_plans(planner_flags(choose_fft_rigor(rigor, nx_ * ny_)));
  if (!forward_plan_ || !backward_plan_) throw Error("FFT: FFTW could not plan the transform");
  real().setZero();
  spectrum().setZero();
}

RealFft2d::~RealFft2d() {
  std::lock_guard lock(planner_mutex());
  destroy(forward_plan_);
  destroy(backward_plan_);
  fftw_free(real_);
  fftw_free(spectrum_);
}

void RealFft2d::forward() {
  fftw_execute(forward_plan_);
}
void RealFft2d::backward() {
  fftw_execute(backward_plan_);
}

void RealFft2d::forward(const HeightMap& in, SpectrumMap& out) {
  real() = in;
  forward();
  out = spectrum();
}

void RealFft2d::backward(const SpectrumMap& in, HeightMap& out) {
  spectrum() = in;
  backward();
  out = real();
}

namespace {
// Nanoseconds, so that the sum is an integer atomic (plans are made on several threads at once).
std::atomic<std::int64_t>& planning_nanoseconds() {
  static std::atomic<std::int64_t> total{0};
  return total;
}
}  // namespace

double fftw_planning_seconds() {
  return static_cast<double>(planning_nanoseconds().load()) * 1e-9;
}

FftwPlanningClock::FftwPlanningClock() : start_(std::chrono::steady_clock::now()) {}

FftwPlanningClock::~FftwPlanningClock() {
  const auto elapsed = std::chrono::steady_clock::now() - start_;
  planning_nanoseconds() += std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count();
}

void set_fft_work(const FftWork& work) {
  std::lock_guard lock(work_mutex());
  work_setting() = work;
}

FftWork fft_work() {
  std::lock_guard lock(work_mutex());
  return work_setting();
}

FftRigor choose_fft_rigor(FftRigor asked, Index points) {
  if (asked != FftRigor::by_work) return asked;
  if (points < kMinPointsForMeasuredPlans) return FftRigor::estimate;
  const FftWork work = fft_work();
  return work.wisdom_kept || work.expected_applications > kPayBackApplications ? FftRigor::measure
                                                                               : FftRigor::estimate;
}

std::unique_lock<std::mutex> lock_fftw_planner() {
  initialise_fftw_threads_once();
  return std::unique_lock<std::mutex>(planner_mutex());
}

RealFft2d& cached_fft(Index nx, Index ny, int threads) {
  // Per thread, so that two threads never share one plan's buffers.
  thread_local std::map<std::tuple<Index, Index, int>, std::unique_ptr<RealFft2d>> cache;
  auto& slot = cache[{nx, ny, threads}];
  if (!slot) slot = std::make_unique<RealFft2d>(nx, ny, threads);
  return *slot;
}

ReproducibleInverseFft2d::ReproducibleInverseFft2d(Index nx, Index ny)
    : nx_(nx), ny_(ny), work_(ny, nx / 2 + 1), result_(ny, nx) {
  check_shape(nx, ny);
  initialise_fftw_threads_once();
  const int nxh = static_cast<int>(nx / 2 + 1);
  const int n_y = static_cast<int>(ny), n_x = static_cast<int>(nx);
  auto* work = reinterpret_cast<fftw_complex*>(work_.data());
  // UNALIGNED: each chunk starts at a different offset, so no alignment may be assumed.
  const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED;
  auto plan_columns = [&](int count) {
    // `count` columns of length ny, stride nxh, adjacent columns 1 apart: in place along y.
    return fftw_plan_many_dft(1, &n_y, count, work, nullptr, nxh, 1, work, nullptr, nxh, 1, FFTW_BACKWARD,
                              flags);
  };
  auto plan_rows = [&](int count) {
    // `count` half-complex rows of nxh entries -> real rows of nx.
    return fftw_plan_many_dft_c2r(1, &n_x, count, work, nullptr, 1, nxh, result_.data(), nullptr, 1, n_x,
                                  flags);
  };
  std::lock_guard lock(planner_mutex());
  const FftwPlanningClock clock;
  fftw_plan_with_nthreads(1);
  const int chunk = static_cast<int>(kLinesPerChunk);
  columns_full_ = plan_columns(chunk);
  if (nxh % chunk) columns_rest_ = plan_columns(nxh % chunk);
  rows_full_ = plan_rows(chunk);
  if (n_y % chunk) rows_rest_ = plan_rows(n_y % chunk);
  if (!columns_full_ || !rows_full_ || ((nxh % chunk) && !columns_rest_) || ((n_y % chunk) && !rows_rest_))
    throw Error("FFT: FFTW could not plan the reproducible inverse transform");
}

ReproducibleInverseFft2d::~ReproducibleInverseFft2d() {
  std::lock_guard lock(planner_mutex());
  destroy(columns_full_);
  destroy(columns_rest_);
  destroy(rows_full_);
  destroy(rows_rest_);
}

void ReproducibleInverseFft2d::backward(const SpectrumMap& in, HeightMap& out, int threads) {
  const Index nxh = nx_ / 2 + 1;
  if (in.rows() != ny_ || in.cols() != nxh)
    throw Error("FFT: spectrum is " + std::to_string(in.rows()) + " x " + std::to_string(in.cols()) +
                ", the plan expects " + std::to_string(ny_) + " x " + std::to_string(nxh));
  work_ = in;
  auto* work = reinterpret_cast<fftw_complex*>(work_.data());
  const Index column_chunks = (nxh + kLinesPerChunk - 1) / kLinesPerChunk;
  const Index row_chunks = (ny_ + kLinesPerChunk - 1) / kLinesPerChunk;
#pragma omp parallel num_threads(team_size(nx_* ny_, threads)) if (team_size(nx_ * ny_, threads) > 1)
  {
#pragma omp for schedule(static)
    for (Index chunk = 0; chunk < column_chunks; ++chunk) {
      const Index first = chunk * kLinesPerChunk;
      fftw_plan plan = (first + kLinesPerChunk <= nxh) ? columns_full_ : columns_rest_;
      fftw_execute_dft(plan, work + first, work + first);
    }
#pragma omp for schedule(static)
    for (Index chunk = 0; chunk < row_chunks; ++chunk) {
      const Index first = chunk * kLinesPerChunk;
      fftw_plan plan = (first + kLinesPerChunk <= ny_) ? rows_full_ : rows_rest_;
      fftw_execute_dft_c2r(plan, work + first * nxh, result_.data() + first * nx_);
    }
  }
  out = result_;
}

}  // namespace contactbench
